// Runs' medians from JSON, the stored reference and its quick check, and the alternating
// comparison's verdict.
#include "tools/liquid_benchmark/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tools::benchmark {

using nlohmann::json;
namespace fs = std::filesystem;

const std::vector<std::string>& pipeline_order() {
  static const std::vector<std::string> order = {
      "liquid.splat",          "liquid.deposit",        "liquid.splat_spread_x", "liquid.splat_spread_y",
      "liquid.splat_spread_z", "liquid.pressure",       "liquid.potential",      "liquid.potential_x",
      "liquid.potential_y",    "liquid.potential_z",    "liquid.grid",           "liquid.particle",
      "liquid.occupancy",      "liquid.raymarch_coarse", "liquid.raymarch_tiles", "liquid.raymarch",
      "liquid.view2d",         "liquid.height_field",
      "fxaa.mark",             "fxaa"};
  return order;
}

std::string short_pass_name(const std::string& name) {
  return name.rfind("liquid.", 0) == 0 ? name.substr(7) : name;
}

namespace {

constexpr int k_reference_format = 1;

[[noreturn]] void malformed(const std::string& source, const std::string& what) {
  throw std::invalid_argument(source + ": " + what);
}

const json& member(const json& object, const std::string& key, const std::string& source, const std::string& path) {
  if (!object.is_object()) malformed(source, (path.empty() ? "the document" : path) + " is not an object");
  const auto it = object.find(key);
  if (it == object.end()) malformed(source, "no " + (path.empty() ? key : path + "." + key));
  return *it;
}

std::string text_member(const json& object, const std::string& key, const std::string& source, const std::string& path) {
  const json& value = member(object, key, source, path);
  if (!value.is_string()) malformed(source, (path.empty() ? key : path + "." + key) + " is not a string");
  return value.get<std::string>();
}

double ms_value(const json& value, const std::string& source, const std::string& path) {
  if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < 0.0)
    malformed(source, path + " is not a time in ms (a finite number >= 0)");
  return value.get<double>();
}

int int_value(const json& value, const std::string& source, const std::string& path) {
  if (!value.is_number_integer()) malformed(source, path + " is not an integer");
  return value.get<int>();
}

RunIdentity identity_of(const json& document, const std::string& source) {
  const json& device = member(document, "device", source, "");
  const json& settings = member(document, "settings", source, "");
  RunIdentity id;
  id.device = text_member(device, "name", source, "device");
  id.driver = text_member(device, "driver", source, "device");
  id.steps_per_frame = int_value(member(settings, "steps_per_frame", source, "settings"), source, "settings.steps_per_frame");
  id.frame_width = int_value(member(settings, "frame_width", source, "settings"), source, "settings.frame_width");
  id.frame_height = int_value(member(settings, "frame_height", source, "settings"), source, "settings.frame_height");
  const json& validation = member(settings, "validation", source, "settings");
  if (!validation.is_boolean()) malformed(source, "settings.validation is not true or false");
  id.validation = validation.get<bool>();
  return id;
}

void add_configuration(RunMedians& run, const std::string& name, std::map<std::string, double> measures) {
  if (run.configurations.count(name)) malformed(run.source, "configuration " + name + " appears twice");
  run.order.push_back(name);
  run.configurations[name] = std::move(measures);
}

// The run in `document` (a reference or results): its date and identity, then a configuration per
// element of its list `key`, named by the element's "name" and measured by `measures_of(element, path)`.
template <class MeasuresOf>
RunMedians run_of(const json& document, const std::string& source, const std::string& key, MeasuresOf measures_of) {
  RunMedians run;
  run.source = source;
  run.date = text_member(document, "date", source, "");
  run.identity = identity_of(document, source);
  const json& list = member(document, key, source, "");
  if (!list.is_array()) malformed(source, key + " is not a list");
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string path = key + "[" + std::to_string(i) + "]";
    std::map<std::string, double> measures = measures_of(list[i], path);
    add_configuration(run, text_member(list[i], "name", source, path), std::move(measures));
  }
  return run;
}

RunMedians medians_of_reference(const json& document, const std::string& source) {
  const json& format = member(document, "format", source, "");
  if (!format.is_number_integer() || format.get<int>() != k_reference_format)
    malformed(source, "reference format " + format.dump() + " is not " + std::to_string(k_reference_format) +
                          " (saved by another version of liquid_benchmark: save it again with --save-reference)");
  return run_of(document, source, "configurations", [&](const json& configuration, const std::string& path) {
    std::map<std::string, double> measures;
    measures["frame"] = ms_value(member(configuration, "frame_ms", source, path), source, path + ".frame_ms");
    const json& gpu = member(configuration, "gpu_ms", source, path);
    if (!gpu.is_object()) malformed(source, path + ".gpu_ms is not an object");
    for (const auto& [pass, ms] : gpu.items()) measures[pass] = ms_value(ms, source, path + ".gpu_ms." + pass);
    return measures;
  });
}

std::string format_ms(double ms) {
  char text[32];
  std::snprintf(text, sizeof text, ms >= 100 ? "%.1f" : "%.2f", ms);
  return text;
}

std::string format_ratios(const std::vector<double>& ratios) {
  std::string text;
  for (double r : ratios) {
    char one[16];
    std::snprintf(one, sizeof one, "%s%.2f", text.empty() ? "" : " ", r);
    text += one;
  }
  return text;
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// "frame" first, then the passes in pipeline order (as the pass table), unknown ones at the end.
std::vector<std::string> measure_order(const std::map<std::string, double>& measures) {
  std::vector<std::string> pipeline = {"frame"};
  pipeline.insert(pipeline.end(), pipeline_order().begin(), pipeline_order().end());
  std::vector<std::string> order;
  for (const std::string& name : pipeline)
    if (measures.count(name)) order.push_back(name);
  for (const auto& [name, ms] : measures)
    if (std::find(pipeline.begin(), pipeline.end(), name) == pipeline.end()) order.push_back(name);
  return order;
}

std::string row_label(const std::string& configuration, const std::string& measure) {
  return configuration + " " + (measure == "frame" ? "frame (wall)" : short_pass_name(measure));
}

// The largest change of a build's median from one round to the next: what a ratio between two
// runs of the same code looks like on this machine.
double round_to_round_change(const std::vector<double>& ms) {
  double change = 0.0;
  for (size_t k = 1; k < ms.size(); ++k)
    if (ms[k - 1] > 0.0) change = std::max(change, std::abs(ms[k] / ms[k - 1] - 1.0));
  return change;
}

}  // namespace

RunMedians medians_of_results(const json& document, const std::string& source) {
  if (!document.is_object() || document.value("tool", "") != "liquid_benchmark")
    malformed(source, "not a liquid_benchmark JSON (no \"tool\": \"liquid_benchmark\")");
  return run_of(document, source, "results", [&](const json& r, const std::string& path) {
    std::map<std::string, double> measures;
    measures["frame"] =
        ms_value(member(member(r, "frame_wall_ms", source, path), "median", source, path + ".frame_wall_ms"), source,
                 path + ".frame_wall_ms.median");
    const json& gpu = member(r, "gpu_ms_per_frame", source, path);
    if (!gpu.is_object()) malformed(source, path + ".gpu_ms_per_frame is not an object");
    for (const auto& [pass, stats] : gpu.items()) {
      const std::string pass_path = path + ".gpu_ms_per_frame." + pass;
      measures[pass] = ms_value(member(stats, "median", source, pass_path), source, pass_path + ".median");
    }
    return measures;
  });
}

RunMedians read_medians(const fs::path& path) {
  const std::string source = path.string();
  if (fs::is_directory(path)) malformed(source, "is a directory, not a JSON file");
  std::ifstream file(path);
  if (!file) malformed(source, "cannot read it (missing or not readable)");
  std::stringstream text;
  text << file.rdbuf();
  json document;
  try {
    document = json::parse(text.str());
  } catch (const json::parse_error& e) {
    malformed(source, std::string("not JSON: ") + e.what());
  }
  if (document.is_object() && document.contains("kind") && document["kind"] == "reference")
    return medians_of_reference(document, source);
  if (document.is_object() && document.contains("kind") && document["kind"] != "results")
    malformed(source, "a liquid_benchmark " + document["kind"].dump() + ", not a run's results or a reference");
  return medians_of_results(document, source);
}

json reference_json(const RunMedians& run, const std::string& command_line) {
  json configurations = json::array();
  for (const std::string& name : run.order) {
    json gpu = json::object();
    double frame = 0.0;
    for (const auto& [measure, ms] : run.configurations.at(name)) {
      if (measure == "frame")
        frame = ms;
      else
        gpu[measure] = ms;
    }
    configurations.push_back({{"name", name}, {"frame_ms", frame}, {"gpu_ms", gpu}});
  }
  const RunIdentity& id = run.identity;
  return {{"tool", "liquid_benchmark"},
          {"kind", "reference"},
          {"format", k_reference_format},
          {"what", "median ms per frame of each configuration: wall time (frame_ms) and each pass's GPU time "
                   "(gpu_ms); read by liquid_benchmark --reference"},
          {"date", run.date},
          {"from", run.source},
          {"command", command_line},
          {"device", {{"name", id.device}, {"driver", id.driver}}},
          {"settings", {{"steps_per_frame", id.steps_per_frame}, {"frame_width", id.frame_width},
                        {"frame_height", id.frame_height}, {"validation", id.validation}}},
          {"configurations", configurations}};
}

void require_same_conditions(const RunIdentity& a, const std::string& a_name, const RunIdentity& b,
                             const std::string& b_name) {
  const auto differ = [&](const std::string& what, const std::string& va, const std::string& vb) {
    throw std::invalid_argument(a_name + " and " + b_name + " differ in " + what + " ('" + va + "' against '" + vb +
                                "'): their timings do not compare");
  };
  if (a.device != b.device) differ("device", a.device, b.device);
  if (a.driver != b.driver) differ("driver", a.driver, b.driver);
  if (a.steps_per_frame != b.steps_per_frame)
    differ("steps per frame", std::to_string(a.steps_per_frame), std::to_string(b.steps_per_frame));
  if (a.frame_width != b.frame_width || a.frame_height != b.frame_height)
    differ("frame size", std::to_string(a.frame_width) + "x" + std::to_string(a.frame_height),
           std::to_string(b.frame_width) + "x" + std::to_string(b.frame_height));
  if (a.validation != b.validation)
    differ("validation", a.validation ? "on" : "off", b.validation ? "on" : "off");
}

int print_reference_check(const RunMedians& reference, const RunMedians& now) {
  struct Row {
    std::string label;
    double reference_ms, now_ms, ratio;
  };
  std::vector<Row> rows;
  std::vector<std::string> missing;
  for (const std::string& name : reference.order) {
    const auto it = now.configurations.find(name);
    if (it == now.configurations.end()) {
      missing.push_back(name);
      continue;
    }
    const auto& ref = reference.configurations.at(name);
    for (const std::string& measure : measure_order(ref)) {
      const auto m = it->second.find(measure);
      if (m == it->second.end() || ref.at(measure) <= 0.0) continue;
      rows.push_back({row_label(name, measure), ref.at(measure), m->second, m->second / ref.at(measure)});
    }
  }
  std::vector<double> ratios;
  for (const Row& r : rows) ratios.push_back(r.ratio);
  const double run_ratio = median_of(ratios);

  std::printf("\nAgainst the reference %s (saved %s on the same device and driver)\n", reference.source.c_str(),
              reference.date.c_str());
  std::printf("This machine's speed drifts (up to 2x over hours), so these ratios are a hint; the verdict on a change "
              "is --baseline-binary's alternating runs.\n");
  std::printf("%-46s %12s %12s %8s %12s\n", "configuration / measure", "reference ms", "this run ms", "ratio",
              "/ run median");
  int warnings = 0;
  for (const Row& r : rows)
    std::printf("%-46s %12s %12s %8.2f %12.2f\n", r.label.c_str(), format_ms(r.reference_ms).c_str(),
                format_ms(r.now_ms).c_str(), r.ratio, run_ratio > 0 ? r.ratio / run_ratio : 0.0);
  std::printf("the run's median ratio: %.2f over %zu measures\n", run_ratio, rows.size());
  for (const std::string& name : missing) std::printf("not in this run: %s\n", name.c_str());
  for (const std::string& name : now.order)
    if (!reference.configurations.count(name)) std::printf("not in the reference: %s\n", name.c_str());
  if (run_ratio > 1.0 + k_reference_tolerance)
    std::printf("note: the whole run is %.2fx the reference: the machine's drift or a general slowdown; alternate "
                "the two builds with --baseline-binary to tell which\n",
                run_ratio);
  for (const Row& r : rows) {
    if (run_ratio <= 0 || r.ratio / run_ratio <= 1.0 + k_reference_tolerance) continue;
    if (r.now_ms - r.reference_ms <= k_min_difference_ms) continue;  // too small to tell on any device
    std::printf("WARNING: %s: %.2fx the reference, %.2fx the run's median ratio (more than %.2f): slower than the "
                "rest of the run; confirm with --baseline-binary\n",
                r.label.c_str(), r.ratio, r.ratio / run_ratio, 1.0 + k_reference_tolerance);
    ++warnings;
  }
  if (warnings == 0 && !rows.empty())
    std::printf("no measure slower than the run as a whole by more than %.0f%%\n", 100 * k_reference_tolerance);
  return warnings;
}

int Comparison::slower() const {
  return int(std::count_if(measures.begin(), measures.end(),
                           [](const MeasureComparison& m) { return m.verdict == "slower"; }));
}

Comparison compare_rounds(const std::vector<RunMedians>& old_rounds, const std::vector<RunMedians>& new_rounds) {
  if (old_rounds.empty() || old_rounds.size() != new_rounds.size())
    throw std::invalid_argument("the comparison needs as many rounds of the old build as of the new, at least one (got " +
                                std::to_string(old_rounds.size()) + " and " + std::to_string(new_rounds.size()) + ")");
  for (const RunMedians& r : old_rounds)
    require_same_conditions(old_rounds[0].identity, old_rounds[0].source, r.identity, r.source);
  for (const RunMedians& r : new_rounds)
    require_same_conditions(old_rounds[0].identity, old_rounds[0].source, r.identity, r.source);

  Comparison c;
  c.rounds = int(old_rounds.size());
  const auto in_all = [](const std::vector<RunMedians>& rounds, const std::string& name) {
    return std::all_of(rounds.begin(), rounds.end(), [&](const RunMedians& r) { return r.configurations.count(name) > 0; });
  };
  for (const std::string& name : old_rounds[0].order)
    if (!in_all(new_rounds, name)) c.only_old.push_back(name);
  for (const std::string& name : new_rounds[0].order)
    if (!in_all(old_rounds, name)) c.only_new.push_back(name);

  for (const std::string& name : new_rounds[0].order) {
    if (!in_all(old_rounds, name) || !in_all(new_rounds, name)) continue;
    for (const std::string& measure : measure_order(new_rounds[0].configurations.at(name))) {
      MeasureComparison m{.configuration = name, .measure = measure};
      bool everywhere = true;
      for (size_t k = 0; k < old_rounds.size() && everywhere; ++k) {
        const auto& o = old_rounds[k].configurations.at(name);
        const auto& n = new_rounds[k].configurations.at(name);
        everywhere = o.count(measure) && n.count(measure) && o.at(measure) > 0.0;
        if (!everywhere) break;
        m.old_ms.push_back(o.at(measure));
        m.new_ms.push_back(n.at(measure));
        m.ratios.push_back(n.at(measure) / o.at(measure));
      }
      if (!everywhere) continue;  // a pass one build does not have
      m.old_median = median_of(m.old_ms);
      m.new_median = median_of(m.new_ms);
      m.ratio_median = median_of(m.ratios);
      m.noise = std::max(round_to_round_change(m.old_ms), round_to_round_change(m.new_ms));
      m.threshold = 1.0 + std::max(m.noise, k_min_change);
      const bool apart = std::abs(m.new_median - m.old_median) > k_min_difference_ms;
      const auto [lo, hi] = std::minmax_element(m.ratios.begin(), m.ratios.end());
      if (apart && *lo > m.threshold)
        m.verdict = "slower";
      else if (apart && *hi < 1.0 / m.threshold)
        m.verdict = "faster";
      else
        m.verdict = "same";
      c.measures.push_back(std::move(m));
    }
  }
  return c;
}

void print_comparison(const Comparison& c, const std::string& old_name, const std::string& new_name) {
  std::printf("\nAlternating comparison over %d round(s): old = %s, new = %s (median ms per frame; GPU per pass)\n",
              c.rounds, old_name.c_str(), new_name.c_str());
  std::printf("rule: slower (WARNING) when every round's new/old ratio is above 1 + max(noise, %.0f%%) and the medians "
              "differ by more than %.2f ms; noise = the largest change of either build's own median from one round "
              "to the next\n",
              100 * k_min_change, k_min_difference_ms);
  if (c.rounds < 2)
    std::printf("note: one round gives no noise estimate (the %.0f%% floor alone applies): use --rounds 3 or more\n",
                100 * k_min_change);
  std::printf("%-46s %10s %10s %7s %8s  %s\n", "configuration / measure", "old ms", "new ms", "new/old", "noise",
              "ratio per round: verdict");
  for (const MeasureComparison& m : c.measures)
    std::printf("%-46s %10s %10s %7.2f %7.0f%%  %s: %s\n", row_label(m.configuration, m.measure).c_str(),
                format_ms(m.old_median).c_str(), format_ms(m.new_median).c_str(), m.ratio_median, 100 * m.noise,
                format_ratios(m.ratios).c_str(), m.verdict.c_str());
  for (const std::string& name : c.only_old) std::printf("only the old build ran %s\n", name.c_str());
  for (const std::string& name : c.only_new) std::printf("only the new build ran %s\n", name.c_str());
  for (const MeasureComparison& m : c.measures) {
    if (m.verdict != "slower") continue;
    std::printf("WARNING: %s: slower, new/old %.2f (rounds: %s), above %.2f in every round (noise %.0f%%)\n",
                row_label(m.configuration, m.measure).c_str(), m.ratio_median, format_ratios(m.ratios).c_str(),
                m.threshold, 100 * m.noise);
  }
  const int slower = c.slower();
  if (slower == 0)
    std::printf("no measure slower beyond the round-to-round noise (%zu compared)\n", c.measures.size());
  else
    std::printf("%d measure(s) slower beyond the round-to-round noise\n", slower);
}

json comparison_json(const Comparison& c, const std::string& old_name, const std::string& new_name) {
  json measures = json::array();
  for (const MeasureComparison& m : c.measures)
    measures.push_back({{"configuration", m.configuration}, {"measure", m.measure}, {"old_ms", m.old_ms},
                        {"new_ms", m.new_ms}, {"ratios", m.ratios}, {"old_median_ms", m.old_median},
                        {"new_median_ms", m.new_median}, {"ratio_median", m.ratio_median}, {"noise", m.noise},
                        {"threshold", m.threshold}, {"verdict", m.verdict}});
  return {{"tool", "liquid_benchmark"},
          {"kind", "comparison"},
          {"old", old_name},
          {"new", new_name},
          {"rounds", c.rounds},
          {"rule", "slower when every round's new/old ratio > 1 + max(noise, " + std::to_string(k_min_change) +
                       ") and the medians differ by more than " + std::to_string(k_min_difference_ms) +
                       " ms; noise = the largest change of either build's median from one round to the next"},
          {"slower", c.slower()},
          {"only_old", c.only_old},
          {"only_new", c.only_new},
          {"measures", measures}};
}

}  // namespace tools::benchmark
