// gvm plan: the fewest setups (or rotary axes, or probe orientations) for a part.
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

#include "cli_common.h"
#include "commands.h"
#include "gvm/analysis_proto.h"
#include "gvm/planner/plan.h"
#include "plan_report.h"
#include "remote_client.h"

namespace gvm::cli {
namespace {

struct PlanArgs {
  AnalysisArgs analysis;
  std::string analysis_json;
  v1::PlanOptions options;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);) out.push_back(part);
  if (!s.empty() && s.back() == sep) out.push_back("");
  return out;
}

bool parse_head(const std::string& text, v1::ProbeHead* head) {
  const std::vector<std::string> f = split(text, ':');
  double v[5];
  if (f.size() != 5) return false;
  for (int i = 0; i < 5; ++i) {
    if (!parse_number(f[i], v[i])) return false;
  }
  head->set_a_min_degrees(v[0]);
  head->set_a_max_degrees(v[1]);
  head->set_b_min_degrees(v[2]);
  head->set_b_max_degrees(v[3]);
  head->set_step_degrees(v[4]);
  return true;
}

// "+z", "-x", "y" or "X,Y,Z".
bool parse_axis(const std::string& text, v1::Vec3* out) {
  std::string t = text;
  double sign = 1;
  if (!t.empty() && (t[0] == '+' || t[0] == '-') && t.size() == 2) {
    sign = t[0] == '-' ? -1 : 1;
    t = t.substr(1);
  }
  if (t == "x" || t == "y" || t == "z") {
    out->set_x(t == "x" ? sign : 0);
    out->set_y(t == "y" ? sign : 0);
    out->set_z(t == "z" ? sign : 0);
    return true;
  }
  const std::vector<std::string> f = split(text, ',');
  double v[3];
  if (f.size() != 3) return false;
  for (int i = 0; i < 3; ++i) {
    if (!parse_number(f[i], v[i])) return false;
  }
  out->set_x(v[0]);
  out->set_y(v[1]);
  out->set_z(v[2]);
  return true;
}

// Reads argv[i] as a plan option; returns an exit status on a usage error.
std::optional<int> parse_plan_arg(const std::vector<std::string>& argv, size_t& i, PlanArgs& args) {
  const std::string& a = argv[i];
  v1::PlanOptions& o = args.options;
  auto value = [&]() -> std::optional<std::string> {
    if (i + 1 >= argv.size()) return std::nullopt;
    return argv[++i];
  };
  auto number = [&](const char* what, double& out) -> std::optional<int> {
    auto v = value();
    if (!v || !parse_number(*v, out) || !std::isfinite(out)) return usage_error(a + " needs " + what);
    return std::nullopt;
  };
  double x = 0;
  if (a == "--mode") {
    auto v = value();
    if (!v || (*v != "setup" && *v != "rotary" && *v != "probe")) {
      return usage_error("--mode needs setup, rotary or probe" + (v ? " (not '" + *v + "')" : std::string()));
    }
    o.set_mode(*v == "setup" ? v1::PLAN_MODE_SETUP : *v == "rotary" ? v1::PLAN_MODE_ROTARY : v1::PLAN_MODE_PROBE);
  } else if (a == "--surfaces") {
    auto v = value();
    if (!v || (*v != "features" && *v != "regions")) return usage_error("--surfaces needs features or regions");
    o.set_surfaces(*v == "features" ? v1::PLAN_SURFACES_FEATURES : v1::PLAN_SURFACES_REGIONS);
  } else if (a == "--concave-only") {
    o.set_concave_only(true);
  } else if (a == "--planar-normal") {
    o.set_planar_normal(true);
  } else if (a == "--split") {
    o.set_split(true);
  } else if (a == "--min-clearance") {
    if (auto e = number("an angle in degrees", x)) return e;
    o.set_min_clearance_degrees(x);
  } else if (a == "--time-limit") {
    if (auto e = number("a number of seconds", x)) return e;
    o.set_time_limit_seconds(x);
  } else if (a == "--cone") {
    if (auto e = number("an angle in degrees", x)) return e;
    o.set_cone_degrees(x);
  } else if (a == "--head") {
    auto v = value();
    if (!v || !parse_head(*v, o.mutable_head())) {
      return usage_error("--head needs A_MIN:A_MAX:B_MIN:B_MAX:STEP in degrees, e.g. 0:105:-180:180:7.5");
    }
  } else if (a == "--part-up") {
    auto v = value();
    if (!v || !parse_axis(*v, o.mutable_part_up())) {
      return usage_error("--part-up needs an axis (+x, -y, z, ...) or a vector X,Y,Z");
    }
  } else if (a == "--analysis-json") {
    auto v = value();
    if (!v) return usage_error("--analysis-json needs an output FILE");
    args.analysis_json = *v;
  } else {
    return usage_error("unknown option '" + a + "'");
  }
  return std::nullopt;
}

// The planner names proto fields; the command line names its flags.
std::string with_flag_names(const std::string& message) {
  static const std::pair<const char*, const char*> kFlags[] = {
      {"head", "--head"}, {"part_up", "--part-up"}, {"cone_degrees", "--cone"},
      {"min_clearance_degrees", "--min-clearance"}, {"time_limit_seconds", "--time-limit"},
      {"threads", "--threads"}, {"mode", "--mode"}};
  for (const auto& [field, flag] : kFlags) {
    if (message.rfind(field, 0) == 0) return std::string(flag) + " (" + field + ")" + message.substr(std::string(field).size());
  }
  return message;
}

// Progress: phases at debug level, and at info level once planning has taken a while.
planner::PlanControl progress_log() {
  const auto start = std::chrono::steady_clock::now();
  planner::PlanControl control;
  control.progress = [start, last = std::string()](std::string_view phase, size_t done, size_t total) mutable {
    if (phase != last) {
      last = std::string(phase);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      spdlog::log(s > 2 ? spdlog::level::info : spdlog::level::debug, "planning: {} ({}/{}), {:.1f} s",
                  last, done, total, s);
    }
    return true;
  };
  return control;
}

// The JSON files and the report, the same whether the plan was made here or on a daemon.
int emit(const PlanArgs& args, const v1::Plan& plan, const v1::Analysis* analysis) {
  const std::string& json = args.analysis.json;
  if (!json.empty() && !write_output(json, to_json(plan))) return failure("cannot write JSON to '" + json + "'");
  if (analysis && !write_output(args.analysis_json, to_json(*analysis))) {
    return failure("cannot write the analysis JSON to '" + args.analysis_json + "'");
  }
  if (!args.analysis.quiet && json != "-" && args.analysis_json != "-") print_plan(plan, std::cout);
  return 0;
}

}  // namespace

int run_plan(const std::vector<std::string>& argv) {
  PlanArgs args;
  for (size_t i = 0; i < argv.size(); ++i) {
    bool mine = true;
    if (auto exit = parse_analysis_arg(argv, i, args.analysis, &mine)) return *exit;
    if (mine) continue;
    if (auto exit = parse_plan_arg(argv, i, args)) return *exit;
  }
  if (auto exit = check_parts(args.analysis, "plan")) return *exit;
  if (!args.analysis_json.empty() && args.analysis.parts.size() > 1) {
    return usage_error("--analysis-json writes one part's analysis: give one PART with it");
  }
  args.options.set_threads(args.analysis.threads);
  if (Status s = planner::validate(args.options); !s.ok()) return usage_error(with_flag_names(s.message()));
  set_log_level(args.analysis);
  const bool with_analysis = !args.analysis_json.empty();
  if (!args.analysis.server.empty()) {
    return remote_plan(args.analysis, args.options, with_analysis, [&](const std::string&, const v1::PlanResponse& r) {
      return emit(args, r.plan(), with_analysis ? &r.analysis() : nullptr);
    });
  }

  auto analysis = analyze(analyze_request(args.analysis));
  if (!analysis.ok()) return failure(analysis.status().message());
  auto plan = planner::plan(*analysis, args.options, progress_log());
  if (!plan.ok()) return failure(plan.status().message());
  if (!with_analysis) return emit(args, plan->message, nullptr);
  const v1::Analysis message = to_proto(*analysis);
  return emit(args, plan->message, &message);
}

}  // namespace gvm::cli
