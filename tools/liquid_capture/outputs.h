// What a capture leaves in its folder, and the rules that keep a folder to one run: capture.json
// (the run's settings), the numbered frames, PLY and VDB files, stats.csv, summary.json and
// checkpoint.bin. A folder holding another run's files is refused unless --overwrite, and a run
// that stops before its first output removes what it created and leaves the folder as it found it:
// a resumed run's record is never removed, and the files --overwrite replaces are set aside, not
// deleted, until the new run ends well (finished, or stopped by the user); a new run that fails
// removes its own files and puts them back.
#pragma once

#include "tools/liquid_capture/options.h"

#include "liquid/scene.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace capture {

inline const char* k_record_name = "capture.json";
inline const char* k_stats_name = "stats.csv";
inline const char* k_summary_name = "summary.json";
// A record is the scene document (at most liquid::k_max_scene_bytes, printed once more with deeper
// indentation) and a page of settings, one level deeper than the scene: past these it is refused
// before it is parsed.
inline constexpr std::uintmax_t k_max_record_bytes = 4 * liquid::k_max_scene_bytes;
inline constexpr int k_max_record_nesting = liquid::k_max_scene_nesting + 2;
inline const char* k_checkpoint_name = "checkpoint.bin";
// The folder --overwrite moves the replaced run into until the new run ends well. One left by a run
// that was killed is put back by the next run into the folder, or deleted by a resume that ends well.
inline const char* k_set_aside_prefix = ".replaced-run-";
// Added to the set-aside folder's name while files move into or out of it: such a folder holds part
// of the replaced run and the folder the rest, with nothing of a new run; the next run moves its
// files back and deletes nothing.
inline const char* k_incomplete_suffix = ".incomplete";
// What a set-aside folder is renamed to before a run that ended well deletes it: one left by a run
// killed meanwhile is deleted by the next run into the folder.
inline const char* k_discarded_prefix = ".discarded-run-";
// The advisory lock a run holds on its folder (flock), holding the holder's process id.
inline const char* k_lock_name = ".liquid_capture.lock";

// Files of a capture run in `settings.folder`: its fixed names, anything matching its name
// patterns or those of the run recorded there (capture.json), and their .partial temporaries.
std::vector<std::filesystem::path> run_files(const RunSettings& settings);

// The output folder for the length of a run.
class RunFolder {
 public:
  // What the run does to the files already in the folder.
  enum class Mode {
    New,        // refuse a folder holding another run's files
    Overwrite,  // replace them (--overwrite)
    Resume,     // continue the run recorded there: its files are the run's own
    DryRun,     // check only; create and touch nothing
  };
  // Checks the folder before the run: throws std::runtime_error with one line when it holds
  // another run's files (Mode::New), is in use by another run or resume (its lock, naming the
  // holder's process id), or cannot be written; creates it (and its missing parents) unless a dry
  // run, remembering what it created, and locks it for the run's length. A set-aside folder left by
  // a killed --overwrite run is put back first (that run's own files removed, and a line printed),
  // unless resuming: a resume continues that run, so the set-aside waits for the resume's end.
  RunFolder(const RunSettings& settings, Mode mode);
  // With Mode::Overwrite: moves the old run's files into a folder of their own inside this one
  // (k_set_aside_prefix + the process id, named so only once every file is in it), so the new run's
  // files cannot mix with them; called once nothing else can refuse the run. They are deleted when
  // the run ends well, put back otherwise. Throws std::runtime_error with one line when a file
  // cannot be moved, after moving back those already moved.
  void set_old_files_aside();
  // Marks the run as having written an output: from then on the folder stays.
  void wrote_output();
  // The run ended well: it finished, or the user stopped it (Ctrl-C, SIGTERM) after writing
  // something. The replaced run's files set aside are deleted (their folder renamed
  // k_discarded_prefix + the process id first).
  void ended_well();
  // Whether the run's end, unless it ends well, puts a replaced run back (removing the new run's
  // files), so a failed run need not write its summary.
  bool puts_back_on_failure() const { return mode_ == Mode::Overwrite && !set_aside_.empty(); }
  // Unless the run ended well: with files set aside, removes the new run's files and puts the old
  // ones back; otherwise, before the first output, takes back what the run made. A resumed run's
  // folder is never taken back. Releases the lock.
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  const std::filesystem::path& path() const { return folder_; }

 private:
  void lock();
  void unlock();
  // Set-aside folders a killed run left, by their state (k_incomplete_suffix, k_discarded_prefix):
  // put back, deleted, or a whole one with Mode::Resume kept for the resume's end.
  void recover_set_aside();
  // Removes the files of the run being given up (fixed names, and `new_run`'s patterns), then moves
  // the set-aside files back and removes their folder.
  void put_back(const std::vector<NamePattern>& new_run);
  // Moves every file in `from` back into the folder, then removes `from`; false if any stays.
  bool move_back(const std::filesystem::path& from);
  std::filesystem::path folder_;
  std::vector<NamePattern> patterns_;  // the new run's names, to remove its files when putting back
  std::vector<std::filesystem::path> created_, old_files_;
  std::filesystem::path set_aside_;  // where the old run's files are, while they are there
  int lock_fd_ = -1;                 // k_lock_name, locked for the run's length
  Mode mode_;
  bool kept_ = false, ended_well_ = false;
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
