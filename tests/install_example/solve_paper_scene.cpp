// Uses the installed hpcontact library: the paper's §7 scene with the friction problem (15),
// solved through the driver as `hpcontact solve` does; prints the energy and writes the outputs
// and the scene (OUT_DIR/scene.toml, for `hpcontact solve` to compare).
//   solve_paper_scene OUT_DIR
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "driver/scene_run.hpp"
#include "scene/scene_reader.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: solve_paper_scene OUT_DIR\n");
    return 2;
  }
  try {
    // 1. The scene: the built-in §7 scene with one effect (any scene file works with read_scene).
    const auto scene =
        hpcontact::scene::parse_scene(hpcontact::scene::paper_scene_text(), "example",
                                      {{"run.effects", std::vector<std::string>{"friction_s"}, "solve_paper_scene"}});
    // 2. Solve and write DIR/summary.json, boundary and VTU files.
    hpcontact::driver::SceneRunOptions options;
    options.out = argv[1];
    const hpcontact::driver::RunResult result = hpcontact::driver::run_scene(scene, options);
    // 3. Report.
    std::FILE* file = std::fopen((std::string(argv[1]) + "/scene.toml").c_str(), "w");
    if (!file || std::fputs(hpcontact::scene::paper_scene_text().c_str(), file) < 0 || std::fclose(file) != 0) {
      std::fprintf(stderr, "error: cannot write %s/scene.toml\n", argv[1]);
      return 4;
    }
    std::printf("friction_s: energy = %.17g\n", result.contact("friction_s").energy);
  } catch (const hpcontact::InputError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 2;
  }
  return 0;
}
