// The paper's figures (Guay, "Simple, Rasterization-based Liquids", GPU Pro 5, section 7), all
// measured on an NVIDIA Quadro 2000M with one solver step and the rendering per frame: the one
// place the benchmark's comparison takes them from.
#pragma once

#include <optional>
#include <string>

namespace tools::benchmark {

// One figure of the chapter for a scene.
struct PaperFigure {
  double fps = 0.0;      // the chapter's method, simulation + rendering
  double sph_fps = 0.0;  // the DirectX 11 SDK SPH sample on the same laptop (2D only); 0 = none
  std::string what;
};

// The chapter's figure for a scene of assets/scenes (by file stem), or nothing when it gives none.
inline std::optional<PaperFigure> paper_figure(const std::string& scene) {
  if (scene == "paper_2d_16k") return PaperFigure{830, 567, "2D, 256^2 grid, 16k particles"};
  if (scene == "paper_2d_32k") return PaperFigure{510, 325, "2D, 256^2 grid, 32k particles"};
  if (scene == "paper_2d_64k") return PaperFigure{296, 169, "2D, 256^2 grid, 64k particles"};
  if (scene == "paper_3d") return PaperFigure{35, 0, "3D, 96^3 grid, 125k particles, raymarch + FXAA at 1024x768"};
  if (scene == "shallow_water") return PaperFigure{130, 0, "shallow water, 256^2 grid, 42k particles"};
  return std::nullopt;
}

inline constexpr const char* k_paper_device = "NVIDIA Quadro 2000M";
inline constexpr const char* k_paper_source =
    "M. Guay, Simple, Rasterization-based Liquids, GPU Pro 5 (2014), section 7";

}  // namespace tools::benchmark
