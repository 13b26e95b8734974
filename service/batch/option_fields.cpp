#include "option_fields.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/message.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

namespace gvm::batch {
namespace {

namespace pb = google::protobuf;

template <class T>
bool number(const std::string& text, T& out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && ptr == end;
}

std::vector<std::string> dotted(const std::string& path) {
  std::vector<std::string> out;
  std::istringstream in(path);
  for (std::string word; std::getline(in, word, '.');) out.push_back(word);
  return out;
}

// The message holding the field at `path` inside `root`, and the field; null if none.
std::pair<pb::Message*, const pb::FieldDescriptor*> locate(pb::Message& root, const std::string& path) {
  pb::Message* m = &root;
  const std::vector<std::string> words = dotted(path);
  for (size_t i = 0; i < words.size(); ++i) {
    const pb::FieldDescriptor* f = m->GetDescriptor()->FindFieldByName(words[i]);
    if (!f || f->is_repeated()) return {nullptr, nullptr};
    if (i + 1 == words.size()) return {m, f};
    if (f->cpp_type() != pb::FieldDescriptor::CPPTYPE_MESSAGE) return {nullptr, nullptr};
    m = m->GetReflection()->MutableMessage(m, f);
  }
  return {nullptr, nullptr};
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

const pb::EnumValueDescriptor* enum_value(const pb::EnumDescriptor* e, const std::string& text) {
  const std::string want = upper(text);
  for (int i = 0; i < e->value_count(); ++i) {
    const std::string& name = e->value(i)->name();
    const bool suffix = name.size() > want.size() && name.compare(name.size() - want.size(), want.size(), want) == 0 &&
                        name[name.size() - want.size() - 1] == '_';
    if (name == want || suffix) return e->value(i);
  }
  return nullptr;
}

std::string enum_names(const pb::EnumDescriptor* e) {
  std::string out;
  for (int i = 1; i < e->value_count(); ++i) out += (i > 1 ? ", " : "") + e->value(i)->name();
  return out;
}

// Sets a scalar field from text; the empty string on success, else what it needs.
std::string set_scalar(pb::Message& m, const pb::FieldDescriptor* f, const std::string& v) {
  const pb::Reflection* r = m.GetReflection();
  switch (f->cpp_type()) {
    case pb::FieldDescriptor::CPPTYPE_DOUBLE: {
      double x = 0;
      if (!number(v, x) || !std::isfinite(x)) return "a finite number";
      r->SetDouble(&m, f, x);
      return {};
    }
    case pb::FieldDescriptor::CPPTYPE_UINT32: {
      uint32_t x = 0;
      if (!number(v, x)) return "a whole number >= 0";
      r->SetUInt32(&m, f, x);
      return {};
    }
    case pb::FieldDescriptor::CPPTYPE_BOOL:
      if (v != "true" && v != "false" && v != "1" && v != "0") return "true or false";
      r->SetBool(&m, f, v == "true" || v == "1");
      return {};
    case pb::FieldDescriptor::CPPTYPE_ENUM:
      if (const pb::EnumValueDescriptor* e = enum_value(f->enum_type(), v)) {
        r->SetEnum(&m, f, e);
        return {};
      }
      return "one of " + enum_names(f->enum_type());
    case pb::FieldDescriptor::CPPTYPE_MESSAGE:
      return "one of its fields named, e.g. '" + f->name() + "." + f->message_type()->field(0)->name() + "'";
    default:
      return "a field gvm batch can set from CSV";
  }
}

}  // namespace

Status set_column(v1::BatchPart& part, const std::string& column, const std::string& value) {
  if (column == "part") part.set_part(value);
  else if (column == "groups") part.set_groups(value);
  else if (column == "name") part.set_name(value);
  if (column == "part" || column == "groups" || column == "name") return {};
  if (column == "threads" || column.ends_with(".threads")) {
    return InvalidArgument("column 'threads': the threads are the batch's (--threads), not a part's");
  }
  auto [m, f] = locate(*part.mutable_plan(), column);
  if (!f) std::tie(m, f) = locate(*part.mutable_analyze(), column);
  if (!f) {
    return InvalidArgument("column '" + column +
                           "' is neither part, groups, name nor a field of PlanOptions or AnalyzeOptions");
  }
  const std::string needs = set_scalar(*m, f, value);
  if (!needs.empty()) return InvalidArgument("column '" + column + "' needs " + needs + " (not '" + value + "')");
  return {};
}

}  // namespace gvm::batch
