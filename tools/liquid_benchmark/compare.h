// Catching a pass that got slower: a run's medians read from its JSON (or from a stored
// reference), a quick check against a stored reference, and the verdict of alternating runs of two
// builds. All of it works on saved JSON, with no device, so it is tested without a GPU.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace tools::benchmark {

// What a timing depends on besides the code: two runs compare only when these are equal.
struct RunIdentity {
  std::string device, driver;
  int steps_per_frame = 1;
  int frame_width = 0, frame_height = 0;
  bool validation = false;
};

// One run's medians, in ms: per configuration, "frame" (wall time per frame) and each pass's GPU
// time per frame (its full name, "liquid.splat").
struct RunMedians {
  std::string source;  // the file it was read from, for messages
  std::string date;
  RunIdentity identity;
  std::vector<std::string> order;  // configurations in run order
  std::map<std::string, std::map<std::string, double>> configurations;
};

// The medians of a benchmark JSON document (benchmark_json()); throws std::invalid_argument
// "<source>: <what is wrong>" when it is not one.
RunMedians medians_of_results(const nlohmann::json& document, const std::string& source);

// A benchmark JSON file or a stored reference, told apart by its "kind"; one-line errors naming
// the file when it is missing or malformed.
RunMedians read_medians(const std::filesystem::path& path);

// The stored reference of a run: its identity and medians (kind "reference").
nlohmann::json reference_json(const RunMedians& run, const std::string& command_line);

// Throws std::invalid_argument naming the first difference (device, driver, steps per frame,
// frame size, validation) when `a` and `b` were measured under different conditions.
void require_same_conditions(const RunIdentity& a, const std::string& a_name, const RunIdentity& b,
                             const std::string& b_name);

// A pass slower than the run as a whole by more than this (ratio to the reference over the run's
// median ratio) gets a WARNING in the reference check.
inline constexpr double k_reference_tolerance = 0.25;

// Below this difference of medians no measure is called slower, in either check.
inline constexpr double k_min_difference_ms = 0.05;

// The reference check: per measure the ratio now/reference and that ratio over the run's median
// ratio (which takes out the machine's drift as far as it slows every pass alike); prints the
// table and a WARNING line per measure slower than the run as a whole beyond
// k_reference_tolerance and k_min_difference_ms. Returns the number of warnings.
int print_reference_check(const RunMedians& reference, const RunMedians& now);

// The alternating comparison's rule: a measure is slower when every round's new/old ratio exceeds
// 1 + max(noise, k_min_change), noise being the largest change of either build's own median from
// one round to the next, and the medians differ by more than k_min_difference_ms.
inline constexpr double k_min_change = 0.10;

// One measure of one configuration across the rounds.
struct MeasureComparison {
  std::string configuration, measure;  // measure: "frame" or a pass name
  std::vector<double> old_ms, new_ms, ratios;  // per round
  double old_median = 0.0, new_median = 0.0, ratio_median = 0.0;
  double noise = 0.0;      // the largest round-to-round change of either build's median
  double threshold = 0.0;  // 1 + max(noise, k_min_change)
  std::string verdict;     // "slower", "faster" or "same"
};

struct Comparison {
  int rounds = 0;
  std::vector<MeasureComparison> measures;
  std::vector<std::string> only_old, only_new;  // configurations one build ran and the other did not
  int slower() const;
};

// Compares rounds of two builds (old_rounds[k] and new_rounds[k] ran one after the other); both
// lists the same size, at least one round, all under the same conditions (else
// std::invalid_argument).
Comparison compare_rounds(const std::vector<RunMedians>& old_rounds, const std::vector<RunMedians>& new_rounds);

// The comparison's table, then one WARNING line per slower measure.
void print_comparison(const Comparison& c, const std::string& old_name, const std::string& new_name);

nlohmann::json comparison_json(const Comparison& c, const std::string& old_name, const std::string& new_name);

// The passes in pipeline order, for the tables' columns and rows: the solver's (the chapter's
// splat, or the separable splat's deposit and spreads; the pressure and potential passes; grid;
// particle), then the views, then FXAA.
const std::vector<std::string>& pipeline_order();

// "splat" for "liquid.splat": the tables' column names.
std::string short_pass_name(const std::string& name);

}  // namespace tools::benchmark
