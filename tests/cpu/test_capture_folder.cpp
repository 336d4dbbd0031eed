// The capture tool's output folder: under --overwrite the replaced run's files are set aside whole
// or not at all, and a run that cannot set them aside, or fails before it does, leaves them as they
// were; which files are a run's.
#include "tools/liquid_capture/outputs.h"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace {

namespace fs = std::filesystem;

// Every entry's content by name ("<folder>" for a folder).
std::map<std::string, std::string> contents(const fs::path& folder) {
  std::map<std::string, std::string> found;
  for (const auto& entry : fs::directory_iterator(folder)) {
    std::ostringstream bytes;
    if (entry.is_directory())
      bytes << "<folder>";
    else
      bytes << std::ifstream(entry.path(), std::ios::binary).rdbuf();
    found[entry.path().filename().string()] = bytes.str();
  }
  return found;
}

}  // namespace

TEST_CASE("an --overwrite run that cannot set the replaced run aside leaves it as it was", "[capture]") {
  const fs::path folder = fs::path(LIQUID_TEST_OUTPUT_DIR) / "capture_set_aside";
  fs::remove_all(folder);
  fs::create_directories(folder);
  for (const char* name : {"capture.json", "frame_00001.png", "frame_00002.png", "frame_00003.png", "stats.csv"})
    std::ofstream(folder / name) << "the old run's " << name;
  capture::RunSettings settings;
  settings.folder = folder;
  settings.frames = capture::NamePattern::parse("frame_#####.png", "-o", ".png");
  using Mode = capture::RunFolder::Mode;
  const std::string pid = std::to_string(::getpid());
  auto before = contents(folder);

  SECTION("its set-aside folder cannot be made") {
    // Files where the set-aside folder would go (the name has this process's id).
    const std::vector<fs::path> in_the_way{folder / (capture::k_set_aside_prefix + pid),
                                           folder / (capture::k_set_aside_prefix + pid + capture::k_incomplete_suffix)};
    for (const fs::path& path : in_the_way) std::ofstream(path) << "in the way";
    {
      capture::RunFolder run(settings, Mode::Overwrite);
      CHECK_THROWS_WITH(run.set_old_files_aside(), Catch::Contains("cannot set the replaced run's files aside"));
      CHECK_FALSE(run.puts_back_on_failure());
    }
    for (const fs::path& path : in_the_way) fs::remove(path);
  }
  SECTION("a file cannot be moved, after others were") {
    {
      capture::RunFolder run(settings, Mode::Overwrite);
      // Gone after the run listed it: capture.json and frame 1 are moved before frame 2 fails.
      fs::remove(folder / "frame_00002.png");
      before.erase("frame_00002.png");
      CHECK_THROWS_WITH(run.set_old_files_aside(), Catch::Contains("frame_00002.png"));
      CHECK_FALSE(run.puts_back_on_failure());
    }
  }
  SECTION("the run fails before it sets anything aside") {
    capture::RunFolder run(settings, Mode::Overwrite);
  }
  CHECK(contents(folder) == before);
}

TEST_CASE("an --overwrite run that ends well leaves only its own files", "[capture]") {
  const fs::path folder = fs::path(LIQUID_TEST_OUTPUT_DIR) / "capture_set_aside_ended";
  fs::remove_all(folder);
  fs::create_directories(folder);
  for (const char* name : {"capture.json", "frame_00001.png", "frame_00002.png"}) std::ofstream(folder / name) << "old";
  capture::RunSettings settings;
  settings.folder = folder;
  settings.frames = capture::NamePattern::parse("frame_#####.png", "-o", ".png");
  {
    capture::RunFolder run(settings, capture::RunFolder::Mode::Overwrite);
    run.set_old_files_aside();
    CHECK(contents(folder) ==
          std::map<std::string, std::string>{{capture::k_set_aside_prefix + std::to_string(::getpid()), "<folder>"},
                                             {capture::k_lock_name, std::to_string(::getpid())}});
    std::ofstream(folder / "frame_00001.png") << "new";
    run.wrote_output();
    run.ended_well();
  }
  CHECK(contents(folder) == std::map<std::string, std::string>{{"frame_00001.png", "new"}});
}

TEST_CASE("a run's files include its surfaces and meshes and those of the run recorded in the folder", "[capture]") {
  const fs::path folder = fs::path(LIQUID_TEST_OUTPUT_DIR) / "capture_surface_files";
  fs::remove_all(folder);
  fs::create_directories(folder);
  // The recorded run wrote OBJ meshes under names of its own.
  std::ofstream(folder / "capture.json") << R"({"names": {"frames": "frame_#####.png", "particles": null,
    "volumes": null, "surfaces": "s_#####.vdb", "meshes": "m_####.obj"}})";
  for (const char* name : {"s_00001.vdb", "m_0001.obj", "m_0002.obj.partial", "surface_00001.vdb", "mesh_00001.ply",
                           "notes.txt", "m_0001.ply"})
    std::ofstream(folder / name) << "x";
  capture::RunSettings settings;
  settings.folder = folder;
  settings.frames = capture::NamePattern::parse("frame_#####.png", "-o", ".png");
  settings.surfaces = capture::NamePattern::parse("surface_#####.vdb", "--surface-name", ".vdb");
  settings.meshes = capture::NamePattern::parse("mesh_#####.ply", "--mesh-name", ".ply");
  std::vector<std::string> names;
  for (const fs::path& file : capture::run_files(settings)) names.push_back(file.filename().string());
  CHECK(names == std::vector<std::string>{"capture.json", "m_0001.obj", "m_0002.obj.partial", "mesh_00001.ply",
                                          "s_00001.vdb", "surface_00001.vdb"});
}
