// Faults of the machine's resources and of Gmsh: a .geo Gmsh cannot mesh (a bow-tie, an open
// curve loop) is an input error with Gmsh's message, serially and under mpirun, never an abort; a
// mesh size that would fill the memory is refused before meshing; a run that meets its memory
// limit (ulimit -v) ends as "out of memory" with exit 3 within seconds, whether at start-up or in
// the factorization, never hanging; a file size limit (ulimit -f) is an I/O failure.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.hpp"
#include "support/instrumented.hpp"

namespace {

using namespace hpcontact::testing;

const std::string& kMpi = kMpiEnvironment;

// The tutorial's block with its curve loop as given, and a scene on it with `domain` keys added.
std::filesystem::path write_block(const std::filesystem::path& dir, const std::string& name, const std::string& points,
                                  const std::string& loop, const std::string& domain_keys = "") {
  std::ofstream(dir / (name + ".geo")) << points << "Line(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\n"
                                       << "Line(4) = {4, 1};\nCurve Loop(1) = " << loop << ";\n"
                                       << "Plane Surface(1) = {1};\nPhysical Curve(\"contact\") = {1};\n"
                                       << "Physical Curve(\"clamped\") = {3};\nPhysical Surface(\"block\") = {1};\n";
  std::ofstream(dir / (name + ".toml")) << "[domain]\nmesh = \"" << (dir / (name + ".geo")).string() << "\"\n"
                                        << domain_keys << "[boundary]\ncontact_groups = [\"contact\"]\n"
                                        << "dirichlet_groups = [\"clamped\"]\n[contact_mesh]\nratio = 1\n"
                                        << "[discretization]\np = 2\npC = 1\n[data]\nf = \"-1\"\ng = \"-0.2\"\n"
                                        << "[run]\neffects = [\"signorini\"]\n";
  return dir / (name + ".toml");
}

const std::string kBlock =
    "Point(1) = {0, 0, 0, 0.2};\nPoint(2) = {2, 0, 0, 0.2};\nPoint(3) = {2, 1, 0, 0.2};\n"
    "Point(4) = {0, 1.5, 0, 0.2};\n";
// Points 3 and 4 swapped: sides 2 and 4 cross.
const std::string kBowTie =
    "Point(1) = {0, 0, 0, 0.2};\nPoint(2) = {2, 0, 0, 0.2};\nPoint(3) = {0, 1, 0, 0.2};\n"
    "Point(4) = {2, 1.5, 0, 0.2};\n";

TEST(ResourceFaults, GeometryGmshCannotMeshIsAnInputError) {
  const auto dir = scratch("resource_gmsh");
  const auto good = write_block(dir, "block", kBlock, "{1, 2, 3, 4}");
  ASSERT_EQ(run("solve " + good.string() + " --out " + (dir / "good").string()).exit_code, 0);
  for (const auto& [scene, gmsh_message] :
       {std::pair{write_block(dir, "bow_tie", kBowTie, "{1, 2, 3, 4}"), "Unable to recover the edge"},
        std::pair{write_block(dir, "open_loop", kBlock, "{1, 2, 3}"), "not to be forming a closed loop"}}) {
    for (const std::string& launcher : {std::string(), kMpi + "mpirun -n 2 --oversubscribe "}) {
      const auto result =
          run_command(launcher + HPCONTACT_CLI " solve " + scene.string() + " --out " + (dir / "out").string());
      EXPECT_EQ(result.exit_code, 2) << launcher << result.output;
      EXPECT_NE(result.output.find("Gmsh cannot mesh the geometry"), std::string::npos) << result.output;
      EXPECT_NE(result.output.find(gmsh_message), std::string::npos) << result.output;
      EXPECT_FALSE(std::filesystem::exists(dir / "out"));
    }
  }
}

TEST(ResourceFaults, MeshSizeThatWouldFillTheMemoryIsRefusedBeforeMeshing) {
  const auto dir = scratch("resource_mesh_size");
  const auto scene = write_block(dir, "tiny", kBlock, "{1, 2, 3, 4}", "mesh_size = 1e-7\n");
  const auto start = std::chrono::steady_clock::now();
  const auto result = run("solve " + scene.string() + " --out " + (dir / "out").string());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("key 'domain.mesh_size' = 1e-07"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("a size of at least"), std::string::npos) << result.output;
  EXPECT_LT(seconds, 30.0);
}

// Under the address-space limit the same run fails at start-up (too little for the libraries'
// buffers) or in its factorization, with exit 3 and the limit named; with room it succeeds. The
// sanitizers' shadow memory cannot live under ulimit -v.
TEST(ResourceFaults, MemoryLimitEndsAsOutOfMemory) {
  if (kInstrumented) GTEST_SKIP() << "ulimit -v leaves AddressSanitizer no room";
  for (const char* limit_kb : {"300000", "900000"}) {
    const auto start = std::chrono::steady_clock::now();
    const auto result = run_command(std::string("sh -c 'ulimit -v ") + limit_kb +
                                    "; timeout 120 " HPCONTACT_CLI " infsup --n 96 --p 8 --pc 3'");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(result.exit_code, 3) << limit_kb << ": " << result.output;
    EXPECT_NE(result.output.find("out of memory"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("the address-space limit (ulimit -v)"), std::string::npos) << result.output;
    EXPECT_LT(seconds, 60.0) << limit_kb;
  }
  const auto roomy = run_command("sh -c 'ulimit -v 2500000; " HPCONTACT_CLI " infsup --n 96 --p 8 --pc 3'");
  EXPECT_EQ(roomy.exit_code, 0) << roomy.output;
}

// A file size limit: MPI still starts (a serial run's PMIx store is in memory), and an output
// the limit stops is an I/O failure naming the file, with nothing half-written.
TEST(ResourceFaults, FileSizeLimitIsAnIoFailureOfTheFileItStops) {
  const auto dir = scratch("resource_file_size");
  const auto small = run_command("sh -c 'ulimit -f 4000; " HPCONTACT_CLI " infsup --n 8'");
  EXPECT_EQ(small.exit_code, 0) << small.output;
  // Under mpirun as the user guide says: the launcher's store in memory too.
  const auto ranks = run_command("sh -c 'ulimit -f 4000; PMIX_MCA_gds=hash " + kMpi +
                                 "mpirun -n 2 --oversubscribe " HPCONTACT_CLI " infsup --n 8'");
  EXPECT_EQ(ranks.exit_code, 0) << ranks.output;
  const auto out = dir / "out";
  const auto stopped = run_command("sh -c 'ulimit -f 64; " HPCONTACT_CLI " solve " HPCONTACT_SOURCE_DIR
                                   "/studies/paper/figure1_signorini.toml --n 64 --p 4 --out " +
                                   out.string() + "'");
  EXPECT_EQ(stopped.exit_code, 4) << stopped.output;
  EXPECT_NE(stopped.output.find("File too large"), std::string::npos) << stopped.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find("out.tmp-"), std::string::npos) << entry.path();
}

}  // namespace
