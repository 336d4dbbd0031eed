// What a capture leaves in its folder, and the rules that keep a folder to one run: capture.json
// (the run's settings), the numbered frames, PLY and VDB files, stats.csv, summary.json and
// checkpoint.bin. A folder holding another run's files is refused unless --overwrite, and a run
// that stops before its first output removes what it created.
#pragma once

#include "tools/liquid_capture/options.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace capture {

inline const char* k_record_name = "capture.json";
inline const char* k_stats_name = "stats.csv";
inline const char* k_summary_name = "summary.json";
inline const char* k_checkpoint_name = "checkpoint.bin";

// Files of a capture run in `settings.folder`: its fixed names, anything matching its name
// patterns or those of the run recorded there (capture.json), and their .partial temporaries.
std::vector<std::filesystem::path> run_files(const RunSettings& settings);

// The output folder for the length of a run.
class RunFolder {
 public:
  // Checks the folder before the run: throws std::runtime_error with one line when it holds
  // another run's files (unless `overwrite`) or cannot be written; creates it (and its missing
  // parents) unless `dry_run`, remembering what it created.
  RunFolder(const RunSettings& settings, bool overwrite, bool dry_run);
  // Removes what the checks found (with --overwrite); called once nothing else can refuse the run.
  void remove_old_files();
  // Marks the run as having written an output: from then on the folder stays.
  void wrote_output() { kept_ = true; }
  // Before the first output, a failed or interrupted run takes back what it made.
  ~RunFolder();

  const std::filesystem::path& path() const { return folder_; }

 private:
  std::filesystem::path folder_;
  std::vector<std::filesystem::path> created_, old_files_;
  bool kept_ = false, dry_run_ = false;
};

// stats.csv: rows are appended to stats.csv.partial, flushed after each frame so a long run can be
// watched, and renamed to stats.csv when the run ends (finished, interrupted or failed), so the
// final name always holds complete rows. text() is the whole table so far (checkpoints keep it).
class StatsTable {
 public:
  explicit StatsTable(std::filesystem::path path) : path_(std::move(path)) {}
  // Starts from a table a checkpoint kept (its header and rows).
  void restore(const std::string& text);
  void append(const std::string& header, const std::string& row);
  void finish();
  const std::string& text() const { return text_; }

 private:
  std::filesystem::path partial() const { return std::filesystem::path(path_.string() + ".partial"); }
  void open(std::ios::openmode mode);
  std::filesystem::path path_;
  std::ofstream file_;
  std::string text_;
};

// summary.json from the stats table: frames written, wall time, per-pass median GPU times and the
// diagnostics' extremes, plus `status` ("finished", "interrupted" or the error) and run facts.
std::string summary_json(const std::string& stats_csv, const nlohmann::json& facts);

}  // namespace capture
