// The plot the benchmark issue asks for: time and arrangement size of both occlusion
// methods against |S| * |O_S|, drawn from a gvm.v1.Comparison (so it can be redrawn from
// a saved JSON without recomputing anything).
#pragma once

#include <string>

#include "gvm/v1/benchmark.pb.h"

namespace gvm::bench {

// A self-contained SVG document with two log-log panels side by side: seconds, and #Arrng
// (vertices of every arrangement built), each against |S| * |O_S|, one mark per surface and
// method. Values that cannot go on a log axis (zero) are left out and counted in the
// caption.
std::string comparison_plot_svg(const v1::Comparison& comparison);

}  // namespace gvm::bench
