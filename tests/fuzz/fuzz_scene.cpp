// libFuzzer target: the scene parser must turn any byte string into a Scene or an InputError.
// Anything else (another exception, a crash, a sanitizer report, a hang) is a bug; crashers go
// to tests/fuzz/regressions/, which fuzz/regressions_test.cpp replays in every test run.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    hpcontact::scene::parse_scene(text, "fuzz.toml");
  } catch (const hpcontact::InputError&) {
    // the expected answer to bad input
  }
  return 0;
}
