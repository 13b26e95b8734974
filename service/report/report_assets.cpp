#include "report_assets.h"

// The files are assembled into read-only data by the assembler's .incbin: no
// multi-megabyte generated C++ source, and CMake rebuilds this file when they change.
#define GVM_INCBIN(name, file)                                                      \
  __asm__(".section .rodata\n.global " #name "_begin\n.balign 16\n" #name "_begin:\n" \
          ".incbin \"" file "\"\n.global " #name "_end\n" #name "_end:\n.previous\n"); \
  extern "C" const char name##_begin[];                                            \
  extern "C" const char name##_end[];

GVM_INCBIN(gvm_report_template, GVM_REPORT_TEMPLATE)
GVM_INCBIN(gvm_report_script, GVM_REPORT_SCRIPT)
GVM_INCBIN(gvm_report_style, GVM_REPORT_STYLE)

namespace gvm::report {

std::string_view page_template() { return {gvm_report_template_begin, gvm_report_template_end}; }
std::string_view page_script() { return {gvm_report_script_begin, gvm_report_script_end}; }
std::string_view page_style() { return {gvm_report_style_begin, gvm_report_style_end}; }

}  // namespace gvm::report
