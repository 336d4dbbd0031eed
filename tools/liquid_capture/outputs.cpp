#include "tools/liquid_capture/outputs.h"

#include "engine/io/atomic_file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace capture {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

bool is_fixed_name(const std::string& name) {
  for (const char* fixed : {k_record_name, k_stats_name, k_summary_name, k_checkpoint_name})
    if (name == fixed || name == std::string(fixed) + ".partial") return true;
  return false;
}

// The name patterns of the run recorded in the folder, if any (an unreadable record adds none).
std::vector<NamePattern> recorded_patterns(const fs::path& folder) {
  std::vector<NamePattern> patterns;
  std::ifstream file(folder / k_record_name);
  const json record = json::parse(file, nullptr, /*allow_exceptions=*/false);
  if (!record.is_object() || !record.contains("names") || !record["names"].is_object()) return patterns;
  for (const auto& [kind, extension] : {std::pair{"frames", ".png"}, {"particles", ".ply"}, {"volumes", ".vdb"},
                                        {"surfaces", ".vdb"}, {"meshes", ""}, {"whitewater", ".ply"}}) {
    const json& name = record["names"].value(kind, json());
    if (!name.is_string()) continue;
    try {
      // A mesh is .ply or .obj: its pattern's own extension.
      const std::string ending = *extension ? extension : fs::path(name.get<std::string>()).extension().string();
      patterns.push_back(NamePattern::parse(name.get<std::string>(), kind, ending));
    } catch (const std::invalid_argument&) {
    }
  }
  return patterns;
}

// The files in `folder` with a fixed name or one of `patterns`, and their .partial temporaries.
std::vector<fs::path> files_named(const fs::path& folder, const std::vector<NamePattern>& patterns) {
  std::vector<fs::path> files;
  std::error_code error;
  if (!fs::is_directory(folder, error)) return files;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    if (!entry.is_regular_file(error)) continue;
    const std::string name = entry.path().filename().string();
    if (is_fixed_name(name) ||
        std::any_of(patterns.begin(), patterns.end(), [&](const NamePattern& p) { return p.matches(name, true); }))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The run's own name patterns.
std::vector<NamePattern> own_patterns(const RunSettings& settings) {
  std::vector<NamePattern> patterns{settings.frames};
  for (const auto& [pattern, flag] : settings.optional_outputs()) patterns.push_back(*pattern);
  return patterns;
}

}  // namespace

std::vector<fs::path> run_files(const RunSettings& settings) {
  std::vector<NamePattern> patterns = recorded_patterns(settings.folder);
  for (const NamePattern& p : own_patterns(settings)) patterns.push_back(p);
  return files_named(settings.folder, patterns);
}

RunFolder::RunFolder(const RunSettings& settings, Mode mode)
    : folder_(settings.folder), patterns_(own_patterns(settings)), mode_(mode), kept_(mode == Mode::Resume) {
  const bool dry_run = mode == Mode::DryRun;
  // The folders that do not exist yet, outermost first: the ones this run creates.
  std::vector<fs::path> missing;
  std::error_code error;
  for (fs::path p = fs::absolute(folder_, error); !p.empty() && !fs::exists(p, error); p = p.parent_path()) {
    missing.insert(missing.begin(), p);
    if (p == p.parent_path()) break;
  }
  try {
    if (!dry_run && missing.empty()) recover_set_aside();
    const std::vector<fs::path> existing = run_files(settings);
    if (!existing.empty() && mode == Mode::New) {
      std::string names = existing.front().filename().string();
      if (existing.size() > 1) names += " and " + std::to_string(existing.size() - 1) + " more";
      throw std::runtime_error(folder_.string() + ": holds another capture's files (" + names +
                               "); --overwrite replaces them, or choose another folder");
    }
    if (mode == Mode::Overwrite) old_files_ = existing;
    if (dry_run) {
      const fs::path ancestor = missing.empty() ? fs::absolute(folder_, error) : missing.front().parent_path();
      if (!fs::is_directory(ancestor, error))
        throw std::runtime_error(folder_.string() + ": cannot create the output folder (" + ancestor.string() +
                                 " is not a folder)");
      if (::access(ancestor.c_str(), W_OK | X_OK) != 0)
        throw std::runtime_error(folder_.string() + ": the output folder is not writable");
      return;
    }
    engine::io::ensure_writable_folder(folder_);
    if (lock_fd_ < 0) lock();
  } catch (...) {
    unlock();
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) fs::remove(*it, error);  // only if empty
    throw;
  }
  created_ = missing;
}

void RunFolder::lock() {
  const fs::path path = folder_ / k_lock_name;
  lock_fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) throw std::runtime_error(path.string() + ": cannot create the folder's lock");
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    char holder[32] = {};
    const ssize_t n = ::pread(lock_fd_, holder, sizeof holder - 1, 0);
    ::close(lock_fd_);
    lock_fd_ = -1;
    const std::string pid = n > 0 ? std::string(holder, size_t(n)) : std::string("unknown");
    throw std::runtime_error(folder_.string() + ": in use by another liquid_capture (pid " + pid +
                             "); wait for it to end or stop it first");
  }
  const std::string pid = std::to_string(::getpid());
  if (::ftruncate(lock_fd_, 0) != 0 || ::pwrite(lock_fd_, pid.data(), pid.size(), 0) != ssize_t(pid.size())) {
    const std::string reason = std::strerror(errno);
    unlock();  // the lock file goes too, so a folder this run created can be removed
    throw std::runtime_error(path.string() + ": cannot write the folder's lock (" + reason + ")");
  }
}

void RunFolder::unlock() {
  if (lock_fd_ < 0) return;
  std::error_code error;
  fs::remove(folder_ / k_lock_name, error);  // removed while still held, so no other run locks a stale file
  ::close(lock_fd_);
  lock_fd_ = -1;
}

void RunFolder::recover_set_aside() {
  // By their names' states: .replaced-run-PID/ holds a whole replaced run (the run that set it
  // aside may have written its own files since), .replaced-run-PID.incomplete/ part of one (the
  // rest is still in the folder, and nothing of a new run is), .discarded-run-PID/ a replaced run
  // whose deletion was cut short.
  std::vector<fs::path> found, discarded;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder_, error)) {
    if (!entry.is_directory(error)) continue;
    const std::string name = entry.path().filename().string();
    if (name.rfind(k_set_aside_prefix, 0) == 0) found.push_back(entry.path());
    if (name.rfind(k_discarded_prefix, 0) == 0) discarded.push_back(entry.path());
  }
  if (found.empty() && discarded.empty()) return;
  lock();  // a run still writing here holds it: then that run's set-aside is refused with the lock's line
  for (const fs::path& old : discarded) {
    fs::remove_all(old, error);
    std::printf("liquid_capture: %s: deleted %s/, a replaced run whose deletion was cut short\n", folder_.c_str(),
                old.filename().c_str());
    std::fflush(stdout);
  }
  if (found.empty()) return;
  std::sort(found.begin(), found.end());
  if (found.size() > 1)
    throw std::runtime_error(folder_.string() + ": holds " + std::to_string(found.size()) + " set-aside runs (" +
                             found[0].filename().string() + ", " + found[1].filename().string() +
                             "); keep the one to put back, move its files into the folder, and delete the others");
  const fs::path set_aside = found.front();
  const std::string name = set_aside.filename().string();
  const bool incomplete = name.size() > std::strlen(k_incomplete_suffix) &&
                          name.compare(name.size() - std::strlen(k_incomplete_suffix), std::string::npos,
                                       k_incomplete_suffix) == 0;
  if (incomplete) {
    // Cut short while setting a run aside, or while putting it back: the files go back, and
    // nothing in the folder is deleted.
    if (!move_back(set_aside))
      throw std::runtime_error(folder_.string() + ": cannot put back the files in " + name +
                               "/ (a run that was stopped while moving them); move them into the folder by hand");
    std::printf("liquid_capture: %s: put back the files of a run that a killed --overwrite run was moving in %s/\n",
                folder_.c_str(), name.c_str());
    std::fflush(stdout);
    return;
  }
  set_aside_ = set_aside;
  if (mode_ == Mode::Resume) {
    std::printf("liquid_capture: %s: %s/ holds the run that the run being resumed replaced; it is deleted when the "
                "resume ends well\n", folder_.c_str(), name.c_str());
    return;
  }
  // The killed run failed: its own files go (those named by its record), and the run it replaced comes back.
  put_back(recorded_patterns(folder_));
  if (!set_aside_.empty())
    throw std::runtime_error(folder_.string() + ": cannot put back the files in " + set_aside_.filename().string() +
                             "/ (a run that was killed set them aside); move them into the folder by hand");
  std::printf("liquid_capture: %s: put back the run that a killed --overwrite run had set aside in %s/, and removed "
              "that run's files\n", folder_.c_str(), name.c_str());
  std::fflush(stdout);
}

bool RunFolder::move_back(const fs::path& from) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(from, error))
    fs::rename(entry.path(), folder_ / entry.path().filename(), error);
  return fs::remove(from, error);  // only if every file went back
}

void RunFolder::put_back(const std::vector<NamePattern>& new_run) {
  std::error_code error;
  // The record goes last, so a run killed meanwhile still names the files left to remove.
  std::vector<fs::path> files = files_named(folder_, new_run);
  std::stable_partition(files.begin(), files.end(), [](const fs::path& f) { return f.filename() != k_record_name; });
  for (const fs::path& file : files) fs::remove(file, error);
  // From here the folder holds none of the new run's files: a run killed while the old ones move
  // back leaves .incomplete, whose files the next run moves back, deleting nothing.
  const fs::path moving = set_aside_.string() + k_incomplete_suffix;
  fs::rename(set_aside_, moving, error);
  if (error) return;
  set_aside_ = moving;
  if (move_back(moving)) set_aside_.clear();
}

void RunFolder::set_old_files_aside() {
  if (old_files_.empty()) return;
  // Moved into .incomplete first, renamed to the final name once every file is there: a run killed
  // meanwhile leaves a folder that the next run knows holds only part of the old run.
  const fs::path done = folder_ / (k_set_aside_prefix + std::to_string(::getpid()));
  const fs::path moving = done.string() + k_incomplete_suffix;
  std::error_code error;
  std::vector<fs::path> moved;
  std::string failed = moving.filename().string() + "/";
  if (fs::create_directory(moving, error)) {
    // Renames within one folder: nothing is copied.
    for (const fs::path& file : old_files_) {
      fs::rename(file, moving / file.filename(), error);
      if (error) {
        failed = file.filename().string();
        break;
      }
      moved.push_back(file);
    }
    if (!error) fs::rename(moving, done, error);
    if (!error) {
      set_aside_ = done;
      return;
    }
  } else if (!error) {
    error = std::make_error_code(std::errc::file_exists);
  }
  // Nothing of the new run is written yet: the files moved go back where they were.
  std::error_code ignored;
  bool all_back = true;
  for (const fs::path& file : moved) {
    fs::rename(moving / file.filename(), file, ignored);
    if (ignored) all_back = false;
  }
  if (all_back && fs::is_directory(moving, ignored)) fs::remove(moving, ignored);  // only if empty
  const std::string left = all_back ? "they are left as they were"
                                    : "some are in " + moving.filename().string() + "/, and the next run puts them back";
  throw std::runtime_error(folder_.string() + ": cannot set the replaced run's files aside (" + failed + ": " +
                           error.message() + "); " + left);
}

void RunFolder::wrote_output() { kept_ = true; }

void RunFolder::ended_well() {
  ended_well_ = kept_ = true;
  if (set_aside_.empty()) return;
  // One rename first, so a run killed while the files are deleted leaves a folder that the next run
  // knows to delete, not one it would take for a whole run to put back.
  const fs::path discarded = folder_ / (k_discarded_prefix + std::to_string(::getpid()));
  std::error_code error;
  fs::rename(set_aside_, discarded, error);
  fs::remove_all(error ? set_aside_ : discarded, error);
  set_aside_.clear();
}

RunFolder::~RunFolder() {
  std::error_code error;
  if (!ended_well_ && puts_back_on_failure()) {
    put_back(patterns_);
  } else if (!kept_ && mode_ != Mode::DryRun && (mode_ != Mode::Overwrite || old_files_.empty())) {
    // (with a replaced run not set aside, the record, table and summary here are that run's)
    for (const char* name : {k_record_name, k_stats_name, k_summary_name})
      for (const std::string suffix : {"", ".partial"}) fs::remove(folder_ / (std::string(name) + suffix), error);
  }
  unlock();
  if (!kept_ && mode_ != Mode::DryRun)
    for (auto it = created_.rbegin(); it != created_.rend(); ++it) fs::remove(*it, error);  // only if empty
}

void StatsTable::open(std::ios::openmode mode) {
  file_.open(partial(), mode);
  if (!file_) throw std::runtime_error(partial().string() + ": cannot write");
}

void StatsTable::restore(const std::string& text) {
  text_ = text;
  open(std::ios::trunc);
  file_ << text_;
  file_.flush();
  if (!file_) throw std::runtime_error(partial().string() + ": write failed (disk full?)");
}

void StatsTable::append(const std::string& header, const std::string& row) {
  if (!file_.is_open()) open(std::ios::trunc);
  if (text_.empty()) {
    text_ = header;
    file_ << header;
  }
  text_ += row;
  file_ << row;
  file_.flush();
  if (!file_) throw std::runtime_error(partial().string() + ": write failed (disk full?)");
}

void StatsTable::finish() {
  if (!file_.is_open()) return;  // no frame written: no table
  file_.close();
  std::error_code error;
  fs::rename(partial(), path_, error);
  if (error) throw std::runtime_error(path_.string() + ": cannot rename into place (" + error.message() + ")");
}

std::string summary_json(const std::string& stats_csv, const json& facts) {
  std::istringstream in(stats_csv);
  std::string line, cell;
  std::vector<std::string> columns;
  if (std::getline(in, line)) {
    std::istringstream header(line);
    while (std::getline(header, cell, ',')) columns.push_back(cell);
  }
  std::map<std::string, std::vector<double>> values;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    for (size_t c = 0; c < columns.size() && std::getline(row, cell, ','); ++c) values[columns[c]].push_back(std::stod(cell));
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  };
  // Counts and frame numbers read back as doubles are written as the integers they are.
  const auto number = [](double v) { return v == std::floor(v) && std::abs(v) < 1e15 ? json(int64_t(v)) : json(v); };
  const auto most = [&](const std::string& c) {
    return values[c].empty() ? json(nullptr) : number(*std::max_element(values[c].begin(), values[c].end()));
  };
  const auto least = [&](const std::string& c) {
    return values[c].empty() ? json(nullptr) : number(*std::min_element(values[c].begin(), values[c].end()));
  };
  json summary = facts;
  const std::vector<double>& frames = values["frame"];
  summary["frames_written"] = frames.size();
  summary["first_frame"] = least("frame");
  summary["last_frame"] = most("frame");
  double wall = 0.0;
  for (double ms : values["wall_ms"]) wall += ms;
  summary["frame_wall_ms"] = {{"total", wall}, {"median", median(values["wall_ms"])}, {"max", most("wall_ms")}};
  json passes = json::object();
  for (const std::string& c : columns)
    if (c.rfind("gpu_ms.", 0) == 0) passes[c.substr(7)] = median(values[c]);
  summary["gpu_ms_median_per_frame"] = passes;
  for (const auto& [column, key] : {std::pair{"surface_ms", "surface_export_ms"}, {"whitewater_ms", "whitewater_export_ms"}})
    if (values.count(column)) summary[key] = {{"median", median(values[column])}, {"max", most(column)}};
  summary["extremes"] = {{"max_density_ratio", most("max_density_ratio")},
                         {"max_speed_m_s", most("max_speed_m_s")},
                         {"max_kinetic_energy_J", most("kinetic_energy_J")},
                         {"min_active_particles", least("active_particles")},
                         {"max_active_particles", most("active_particles")},
                         {"min_mass_kg", least("mass_kg")},
                         {"max_mass_kg", most("mass_kg")},
                         {"max_outside_domain", most("outside_domain")},
                         {"max_inside_obstacles", most("inside_obstacles")},
                         {"max_non_finite", most("non_finite")}};
  if (values.count("whitewater_particles"))
    summary["extremes"]["max_whitewater_particles"] = most("whitewater_particles");
  return summary.dump(2) + "\n";
}

}  // namespace capture
