// Command line: --help lists the subcommands, bad input exits with code 2 and leaves
// no output, and the convergence subcommand writes its CSV.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "support/cli_runner.hpp"
#include "support/csv_file.hpp"
#include "support/paper_scene.hpp"

namespace {

using hpcontact::testing::line_of;
using hpcontact::testing::paper_scene_with;
using hpcontact::testing::read_csv;
using hpcontact::testing::run;
using hpcontact::testing::run_command;
using hpcontact::testing::SceneKeyText;
using hpcontact::testing::scratch;
using hpcontact::testing::without_seconds;

const char* kStudy = R"toml([solution]
u  = "sin(1-x)*sin(1-y)"
ux = "-cos(1-x)*sin(1-y)"
uy = "-sin(1-x)*cos(1-y)"
f  = "2*sin(1-x)*sin(1-y)"
[[runs]]
p = [1, 2]
n = [2, 4]
)toml";

}  // namespace

TEST(Cli, HelpListsSubcommands) {
  const auto result = run("--help");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.output.find("convergence"), std::string::npos) << result.output;
}

TEST(Cli, ConvergenceWritesCsvWithDocumentedColumns) {
  const auto dir = scratch("ok");
  std::ofstream(dir / "study.toml") << kStudy;
  const auto result = run("convergence " + (dir / "study.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto csv = read_csv(dir / "out" / "convergence.csv");
  EXPECT_EQ(csv.header_line(), "p,n,refinements,cells,ndofs,h,error_h1,error_l2,seconds,geometry");
  EXPECT_EQ(csv.rows.size(), 4u);
}

TEST(Cli, BadInputExitsWithTwoAndWritesNothing) {
  const auto dir = scratch("bad");
  std::string study = kStudy;
  study.replace(study.find("p = [1, 2]"), 10, "p = [0, 2]");
  std::ofstream(dir / "study.toml") << study;
  const auto result = run("convergence " + (dir / "study.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("runs[0].p"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));

  std::string wrong_f = kStudy;
  wrong_f.replace(wrong_f.find("f  = \"2*"), 8, "f  = \"3*");
  std::ofstream(dir / "wrong_f.toml") << wrong_f;
  const auto inconsistent = run("convergence " + (dir / "wrong_f.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(inconsistent.exit_code, 2);
  EXPECT_NE(inconsistent.output.find("solution.f"), std::string::npos) << inconsistent.output;
}

TEST(Cli, UnknownSubcommandOrMissingFileIsAnError) {
  EXPECT_NE(run("no-such-command").exit_code, 0);
  EXPECT_EQ(run("convergence /nonexistent/study.toml").exit_code, 2);
}

namespace {
std::string alpha_line(const std::string& output) {
  const auto start = output.find("alpha = ");
  return start == std::string::npos ? "" : output.substr(start, output.find('\n', start) - start);
}
}  // namespace

TEST(Cli, InfsupPrintsAlphaAndSceneMatchesBuiltInGeometry) {
  const auto built_in = run("infsup --p 3 --pc 2 --n 8 --ratio 1/2 --eigensolver dense");
  ASSERT_EQ(built_in.exit_code, 0) << built_in.output;
  const auto scene =
      run(std::string("infsup --scene ") + HPCONTACT_TEST_DATA + "/scene_paper.toml --eigensolver dense");
  ASSERT_EQ(scene.exit_code, 0) << scene.output;
  EXPECT_FALSE(alpha_line(built_in.output).empty());
  EXPECT_EQ(alpha_line(scene.output), alpha_line(built_in.output));
  EXPECT_EQ(run("infsup --n 8 --ratio 1/3").exit_code, 2);
}

TEST(Cli, InfsupCsvAndModeFiles) {
  const auto dir = scratch("infsup");
  const std::string csv = (dir / "alpha.csv").string(), mode = (dir / "mode.csv").string();
  for (int k = 0; k < 2; ++k)
    ASSERT_EQ(run("infsup --p 1 --pc 0 --n 4 --ratio 1 --csv " + csv + " --mode " + mode).exit_code, 0);
  const auto alpha = read_csv(csv);
  // The columns of a sweep's alpha.csv: a single run is level 1, h_min the shortest edge on Γ_C.
  EXPECT_EQ(
      alpha.header_line(),
      "problem,norm,p,pC,family,level,n,m,h,h_min,H,ratio,Pi,alpha,alpha_predicted,alpha_error,ndofs,nmult,seconds");
  ASSERT_EQ(alpha.rows.size(), 2u);
  for (const auto& row : alpha.rows)
    EXPECT_EQ(line_of(row).find("signorini,interp,1,0,discontinuous,1,4,4,0.5,0.5,0.5,1,"), 0u) << line_of(row);
  EXPECT_EQ(read_csv(mode).rows.size(), 4u * 20);
}

TEST(Cli, SolveWritesBoundaryCsvVtuAndSummary) {
  const auto dir = scratch("solve");
  const std::string scene = std::string(HPCONTACT_SOURCE_DIR) + "/studies/paper/figure1_signorini.toml";
  const auto result = run("solve " + scene + " --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(read_csv(dir / "out" / "boundary_signorini.csv").header_line().substr(0, 21), "x,u,obstacle,lambda,y");
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "solution_signorini.vtu"));
  std::ifstream summary(dir / "out" / "summary.json");
  const std::string json((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"kkt_residual\""), std::string::npos);
  EXPECT_NE(json.find("\"lambda_unique\": true"), std::string::npos) << json.substr(0, 400);
}

TEST(Cli, SolveWithoutObstacleIsBadInputAndWritesNothing) {
  const auto dir = scratch("solve_bad");
  std::ifstream in(std::string(HPCONTACT_SOURCE_DIR) + "/studies/paper/figure1_signorini.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("g = \"-x^2\""), 10, "");
  std::ofstream(dir / "scene.toml") << text;
  const auto result = run("solve " + (dir / "scene.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("data.g"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(Cli, SolveWithMoreConstraintPointsUsesInteriorPointAndRefusesTooFew) {
  const auto dir = scratch("solve_points");
  const std::string scene = std::string(HPCONTACT_SOURCE_DIR) + "/studies/paper/figure6_friction_s.toml";
  const auto good =
      run("solve " + scene + " --effects friction_s --constraint-points 6 --out " + (dir / "out").string());
  ASSERT_EQ(good.exit_code, 0) << good.output;
  std::ifstream summary(dir / "out" / "summary.json");
  const std::string json((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"interior-point\""), std::string::npos) << json.substr(0, 600);
  EXPECT_NE(json.find("\"active_set_changes\""), std::string::npos);
  const auto bad =
      run("solve " + scene + " --effects friction_s --pc 3 --constraint-points 3 --out " + (dir / "bad").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("--constraint-points"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("p_C + 1 = 4"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
}

// `[solve] fit_free_boundary`: the mesh is graded towards the free boundary of every contact
// problem of the scene (two ends of the contact set of (9), one stick-slip point shared by (13)
// and (15)) before the effects run on it, and the summary says where; a scene that cannot be fitted
// is refused, naming the key.
TEST(Cli, SolveFitsTheMeshToTheFreeBoundaryOfItsProblems) {
  const auto dir = scratch("solve_fit");
  // The §7 scene graded towards (1, 0), p = 8, p_C = 6, fitted to the free boundary of (9) and (15).
  const std::vector<SceneKeyText> fit{{"domain.grading_points", "[[1, 0]]"},
                                      {"domain.grading", "0.2"},
                                      {"domain.grading_layers", "8"},
                                      {"discretization.p", "8"},
                                      {"discretization.pC", "6"},
                                      {"data.g", "\"-x^2\""},
                                      {"solve.fit_free_boundary", "true"},
                                      {"run.effects", "[\"signorini\", \"friction_s\"]"},
                                      {"run.outputs", "[\"summary\"]"}};
  std::ofstream(dir / "fit.toml") << paper_scene_with(fit);
  // (one BLAS thread, as each rank under mpirun has: the fitted points are settled to 1e-6 |Γ_C|
  // only, and round-off of another thread count moves them within that)
  const auto result = run_command("env OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " solve " + (dir / "fit.toml").string() +
                                  " --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream file(dir / "out" / "summary.json");
  const auto summary = nlohmann::json::parse(file);
  const auto& points = summary.at("free_boundary").at("points");
  ASSERT_EQ(points.size(), 3u) << summary.at("free_boundary").dump();
  for (const auto& point : points) EXPECT_DOUBLE_EQ(point[1].get<double>(), -1.0);  // on Γ_C
  EXPECT_LE(summary.at("free_boundary").at("moved").get<double>(), 2e-6);
  // The effects ran on the fitted mesh: 8 edges on Γ_C, and 8 layers on each side of each point.
  EXPECT_EQ(summary.at("edges_on_contact").get<int>(), 8 + 3 * 2 * 8);
  // Under mpirun rank 0 fits and sends the points: the same points and mesh, the same energies.
  const auto parallel = run_command(
      "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -n 2 --oversubscribe "
      "-x OPENBLAS_NUM_THREADS=1 " HPCONTACT_CLI " solve " +
      (dir / "fit.toml").string() + " --out " + (dir / "parallel").string());
  ASSERT_EQ(parallel.exit_code, 0) << parallel.output;
  std::ifstream parallel_file(dir / "parallel" / "summary.json");
  const auto parallel_summary = nlohmann::json::parse(parallel_file);
  EXPECT_EQ(parallel_summary.at("free_boundary").at("points"), points);
  EXPECT_EQ(parallel_summary.at("edges_on_contact"), summary.at("edges_on_contact"));
  for (const char* effect : {"signorini", "friction_s"}) {
    const double energy = summary.at(effect).at("energy").get<double>();
    EXPECT_NEAR(parallel_summary.at(effect).at("energy").get<double>(), energy, 1e-10 * std::abs(energy)) << effect;
  }

  auto infsup_only = fit;
  infsup_only.emplace_back("run.effects", "[\"infsup\"]");
  std::ofstream(dir / "bad.toml") << paper_scene_with(infsup_only);
  const auto bad = run("solve " + (dir / "bad.toml").string() + " --out " + (dir / "bad").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("solve.fit_free_boundary"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
}

TEST(Cli, BenchmarkWritesRatiosAgainstTheBaselineOfTheSameRun) {
  const auto dir = scratch("benchmark");
  std::ofstream(dir / "bench.toml")
      << "[benchmark]\np = 2\npC = 1\nratio = \"1/2\"\nn = [4, 8]\n"
         "kinds = [\"signorini\", \"alpha\", \"alpha_extension\", \"assembled\", \"two_body\", \"three_d_alpha\", "
         "\"startup\"]\n";
  const auto result = run("benchmark " + (dir / "bench.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto csv = read_csv(dir / "out" / "benchmark.csv");
  EXPECT_EQ(csv.header_line(),
            "kind,p,pC,n,m,ndofs,nmult,n_trace,seconds_assembly,seconds_baseline,seconds,ratio,peak_rss_mb,products");
  std::vector<std::string> kinds;
  for (const auto& row : csv.rows) {
    // ratio = seconds / seconds_baseline, both positive
    const std::string line = line_of(row);
    std::vector<double> cells;
    for (std::size_t k = 1; k < row.size(); ++k) cells.push_back(std::stod(row[k]));
    ASSERT_EQ(cells.size(), 13u) << line;
    EXPECT_GT(cells[8], 0.0) << line;
    kinds.push_back(row.front());
    EXPECT_NEAR(cells[10], cells[9] / cells[8], 1e-12 * cells[10]) << line;
  }
  const std::vector<std::string> level{"linear_K",
                                       "signorini",
                                       "linear_AG",
                                       "alpha",
                                       "alpha_extension",
                                       "linear_K_assembled",
                                       "linear_AG_assembled",
                                       "linear_A_two_body",
                                       "two_body_frictionless",
                                       "linear_AG_3d",
                                       "alpha_3d_products",
                                       "alpha_3d_dense"};
  std::vector<std::string> expected{"startup"};  // whole processes, once, before the levels
  expected.insert(expected.end(), level.begin(), level.end());
  expected.insert(expected.end(), level.begin(), level.end());
  EXPECT_EQ(kinds, expected);
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "scaling.csv"));
  std::ofstream(dir / "bad.toml") << "[benchmark]\np = 2\npC = 1\nratio = \"1/3\"\nn = [4]\n";
  const auto bad = run("benchmark " + (dir / "bad.toml").string() + " --out " + (dir / "bad").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("benchmark.n"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
}

// The work–precision study end to end on a small scale: a reference fitted to the free boundary
// (two ends of the contact set of (9)) whose accuracy is its change from the variant before it,
// and a reference that has no coarser discretization is refused, naming the key.
TEST(Cli, WorkPrecisionFitsTheReferenceAndEstimatesItsAccuracy) {
  const auto dir = scratch("work_precision");
  const std::string head =
      "[study]\nscene = \"" + std::string(HPCONTACT_SOURCE_DIR) +
      "/studies/work_precision/base.toml\"\nproblems = [\"signorini\"]\ntolerances = [1e-3]\nrepeats = 1\n"
      "[[family]]\nname = \"p\"\nvary = { \"discretization.p\" = [2, 3], \"discretization.pC\" = [1, 2] }\n"
      "[[family]]\nname = \"adaptive\"\nset = { domain = { n_x = 4, n_y = 4 }, discretization = { p = 2, pC = 0 }, "
      "contact_mesh = { ratio = 1 }, run = { effects = [\"signorini\"] }, adapt = { target = 1e-4 } }\n";
  std::ofstream(dir / "study.toml") << head << "[[reference]]\nproblem = \"signorini\"\nfit_free_boundary = true\n"
                                    << "set = { domain = { grading_points = [[1, 0]], grading = 0.2, grading_layers = "
                                       "8 }, contact_mesh = { ratio = 1 } }\n"
                                    << "vary = { \"discretization.p\" = [6, 8], \"discretization.pC\" = [4, 6] }\n";
  const auto result = run("work-precision " + (dir / "study.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto csv = read_csv(dir / "out" / "reference.csv");
  EXPECT_EQ(
      csv.header_line(),
      "problem,energy,energy_coarser,accuracy_energy,accuracy_lambda,ndofs,seconds,free_boundary,free_boundary_moved");
  ASSERT_FALSE(csv.rows.empty());
  const auto& cells = csv.rows.front();
  ASSERT_EQ(cells.size(), 9u) << line_of(cells);
  const double energy = std::stod(cells[1]), coarser = std::stod(cells[2]), accuracy = std::stod(cells[3]);
  EXPECT_NEAR(accuracy, std::abs(energy - coarser), 1e-15);
  EXPECT_LT(accuracy, 1e-7) << "p 6 -> 8 on the fitted mesh";
  EXPECT_EQ(std::count(cells[7].begin(), cells[7].end(), ';'), 1) << "two ends of the contact set: " << cells[7];
  EXPECT_LE(std::stod(cells[8]), 2e-6);
  // The adaptive family: one row per step, its time the adaptivity's so far, its error falling.
  const auto runs = read_csv(dir / "out" / "work_precision.csv");
  std::vector<double> adaptive_seconds, adaptive_errors;
  for (const auto& row : runs.rows)
    if (row.at(10) == "adaptive")
      adaptive_seconds.push_back(std::stod(row.at(9))), adaptive_errors.push_back(std::stod(row.at(7)));
  ASSERT_GE(adaptive_errors.size(), 3u);
  EXPECT_TRUE(std::is_sorted(adaptive_seconds.begin(), adaptive_seconds.end()));
  EXPECT_LT(adaptive_errors.back(), 1e-2 * adaptive_errors.front());
  EXPECT_LT(adaptive_errors.back(), 1e-4);

  std::ofstream(dir / "bad.toml") << head
                                  << "[[reference]]\nproblem = \"signorini\"\nset = { discretization = { p = 4 } }\n";
  const auto bad = run("work-precision " + (dir / "bad.toml").string() + " --out " + (dir / "bad").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("reference.set.domain.refinements"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
}

// `mpirun -n 4 hpcontact sweep` hands the groups (split by ratio: more ranks than levels) to the
// ranks and writes the same
// alpha.csv and verdicts.csv as a serial run (compared without the timing column). Both runs use
// one BLAS thread per process, so that every floating-point operation is the same.
TEST(Cli, SweepUnderMpirunWritesTheSerialCsv) {
  const auto dir = scratch("sweep_mpi");
  std::filesystem::copy_file(HPCONTACT_SOURCE_DIR "/studies/stability/square.toml", dir / "square.toml");
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"square.toml\"\np = \"1..3\"\npC = \"0..2\"\n"
                                       "levels = { \"domain.n_x\" = [4, 8, 16], \"domain.n_y\" = [4, 8, 16] }\n"
                                       "ratio = [1, \"1/2\"]\nnorm = [\"interp\", \"extension\"]\n"
                                       "problem = [\"signorini\", \"friction\"]\n";
  const std::string env = "env OPENBLAS_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ";
  const auto serial = run_command(env + HPCONTACT_CLI " sweep " + (dir / "sweep.toml").string() + " --out " +
                                  (dir / "serial").string());
  ASSERT_EQ(serial.exit_code, 0) << serial.output;
  // 4 ranks on 3 levels: the groups are split by ratio (more processes than levels).
  const auto parallel = run_command(env + "mpirun -n 4 --oversubscribe " HPCONTACT_CLI " sweep " +
                                    (dir / "sweep.toml").string() + " --out " + (dir / "parallel").string());
  ASSERT_EQ(parallel.exit_code, 0) << parallel.output;
  EXPECT_NE(parallel.output.find("on 4 ranks"), std::string::npos) << parallel.output;
  const std::string serial_alpha = without_seconds(dir / "serial" / "alpha.csv");
  EXPECT_EQ(std::count(serial_alpha.begin(), serial_alpha.end(), '\n'), 1 + 2 * 2 * 6 * 3 * 2);
  EXPECT_EQ(serial_alpha, without_seconds(dir / "parallel" / "alpha.csv"));
  std::ifstream a(dir / "serial" / "verdicts.csv"), b(dir / "parallel" / "verdicts.csv");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}), std::string(std::istreambuf_iterator<char>(b), {}));
}

// `hpcontact sweep --shard i/N` on four independent processes (a batch job array; more than the
// study's three levels, so the groups are split by ratio) and on three (whole groups), and `--merge`
// of their folders give the serial alpha.csv and verdicts.csv; a slice resumed after another
// slice's rows are stored still owns the same groups; a missing slice is refused by name.
TEST(Cli, ShardedSweepMergesIntoTheSerialCsv) {
  const auto dir = scratch("sweep_shards");
  const std::string study = HPCONTACT_SOURCE_DIR "/studies/stability/quick.toml";
  const std::string env = "env OPENBLAS_NUM_THREADS=1 ";
  const auto serial = run_command(env + HPCONTACT_CLI " sweep " + study + " --out " + (dir / "serial").string());
  ASSERT_EQ(serial.exit_code, 0) << serial.output;
  std::string merge_dirs;
  int rows = 0;
  for (int i = 0; i < 4; ++i) {
    const auto out = dir / ("shard" + std::to_string(i));
    const auto slice = run_command(env + HPCONTACT_CLI " sweep " + study + " --shard " + std::to_string(i) +
                                   "/4 --out " + out.string());
    ASSERT_EQ(slice.exit_code, 0) << slice.output;
    EXPECT_FALSE(std::filesystem::exists(out / "verdicts.csv"));
    std::ifstream in(out / "alpha.csv");
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n')) - 1;
    EXPECT_GT(lines, 0) << "slice " << i << " computed nothing";
    rows += lines;
    merge_dirs += " " + out.string();
  }
  const std::string serial_alpha = without_seconds(dir / "serial" / "alpha.csv");
  EXPECT_EQ(rows + 1, std::count(serial_alpha.begin(), serial_alpha.end(), '\n'));  // disjoint slices
  // Resuming slice 1 computes nothing more (its groups do not move): its file stays byte for byte,
  // seconds included.
  auto text_of = [](const std::filesystem::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string slice1 = text_of(dir / "shard1" / "alpha.csv");
  const auto again =
      run_command(env + HPCONTACT_CLI " sweep " + study + " --shard 1/4 --out " + (dir / "shard1").string());
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(text_of(dir / "shard1" / "alpha.csv"), slice1);
  const auto missing = run(" sweep " + study + " --merge " + (dir / "shard0").string() + " " +
                           (dir / "shard1").string() + " --out " + (dir / "merged").string());
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("points are in none of them"), std::string::npos) << missing.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "merged" / "alpha.csv"));
  const auto merged = run(" sweep " + study + " --merge" + merge_dirs + " --out " + (dir / "merged").string());
  ASSERT_EQ(merged.exit_code, 0) << merged.output;
  EXPECT_EQ(serial_alpha, without_seconds(dir / "merged" / "alpha.csv"));
  std::ifstream a(dir / "serial" / "verdicts.csv"), b(dir / "merged" / "verdicts.csv");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}), std::string(std::istreambuf_iterator<char>(b), {}));
  // Three slices (no more than the levels: whole (n, p) groups) merge into the serial file too.
  std::string whole_dirs;
  for (int i = 0; i < 3; ++i) {
    const auto out = dir / ("whole" + std::to_string(i));
    const auto slice = run_command(env + HPCONTACT_CLI " sweep " + study + " --shard " + std::to_string(i) +
                                   "/3 --out " + out.string());
    ASSERT_EQ(slice.exit_code, 0) << slice.output;
    whole_dirs += " " + out.string();
  }
  const auto whole = run(" sweep " + study + " --merge" + whole_dirs + " --out " + (dir / "merged_whole").string());
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  EXPECT_EQ(serial_alpha, without_seconds(dir / "merged_whole" / "alpha.csv"));
  // A folder repeating slice 0's points with other numbers: the first folder's rows are kept, with a
  // warning naming one such point.
  std::filesystem::create_directories(dir / "conflict");
  std::string conflicting = text_of(dir / "shard0" / "alpha.csv");
  const auto first_row_end = conflicting.find('\n', conflicting.find('\n') + 1);
  conflicting.insert(conflicting.rfind(',', first_row_end), "9");  // nmult of the first row, one digit more
  std::ofstream(dir / "conflict" / "alpha.csv") << conflicting;
  std::filesystem::copy_file(dir / "shard0" / "sweep_identity.txt", dir / "conflict" / "sweep_identity.txt");
  const auto remerged = run(" sweep " + study + " --merge" + merge_dirs + " " + (dir / "conflict").string() +
                            " --out " + (dir / "remerged").string());
  ASSERT_EQ(remerged.exit_code, 0) << remerged.output;
  EXPECT_NE(remerged.output.find("with other numbers"), std::string::npos) << remerged.output;
  EXPECT_EQ(serial_alpha, without_seconds(dir / "remerged" / "alpha.csv"));
  for (const char* bad : {"3/3", "1/0", "-1/2", "a/b", "2"}) {
    const auto refused = run(" sweep " + study + " --shard " + bad + " --out " + (dir / "bad").string());
    EXPECT_EQ(refused.exit_code, 2) << bad << ": " << refused.output;
    EXPECT_NE(refused.output.find("--shard"), std::string::npos) << refused.output;
  }
}

// `mpirun -n 2 hpcontact solve` factorizes K and A_G over the ranks (by default substructuring:
// the cells split by PT-Scotch, CHOLMOD per rank, a dense interface problem; and with
// MATIS + BDDC on 3 ranks, so that the parts meet at a cross point) and gives the serial run's
// contact solution and α: every number of the boundary CSV to 1e-8 of its column's size, the
// energies and α to 1e-10.
// `mpirun -n 2 hpcontact infsup` factorizes A_G over the ranks and prints the serial α, in both
// H^{-1/2} realizations and with the three distributed solvers; only rank 0 prints.
// The §7 scene in both norms, and an elastic scene in the extension norm (whose references rank 0
// alone refines and sends in parts, as for the scalar pairing).
TEST(Cli, InfsupUnderMpirunGivesTheSerialAlpha) {
  const std::string env = "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ";
  const std::string elastic = " --scene " + std::string(HPCONTACT_SOURCE_DIR) + "/studies/elasticity/square.toml";
  for (const std::string& norm : std::vector<std::string>{"interp", "extension", "extension" + elastic}) {
    const std::string arguments = " infsup --n 16 --p 3 --pc 2 --ratio 1/2 --norm " + norm;
    const auto serial = run(arguments);
    ASSERT_EQ(serial.exit_code, 0) << serial.output;
    for (const char* solver : {"substructuring", "mumps", "bddc"}) {
      const auto parallel = run_command(env + "mpirun -n 2 --oversubscribe " + HPCONTACT_CLI + arguments +
                                        " --distributed-solver " + solver);
      ASSERT_EQ(parallel.exit_code, 0) << parallel.output;
      const std::string key = "alpha = ";
      ASSERT_NE(parallel.output.find(key), std::string::npos) << parallel.output;
      EXPECT_EQ(parallel.output.find(key), parallel.output.rfind(key))
          << "printed by one rank only: " << parallel.output;
      const double alpha = std::stod(serial.output.substr(serial.output.find(key) + key.size()));
      const double alpha_mpi = std::stod(parallel.output.substr(parallel.output.find(key) + key.size()));
      EXPECT_NEAR(alpha_mpi, alpha, 1e-10 * alpha) << norm << ", " << solver;
    }
  }
}

TEST(Cli, SolveUnderMpirunGivesTheSerialSolutionAndAlpha) {
  const std::string env = "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ";
  auto number_after = [](const std::string& text, const std::string& key) {
    const auto at = text.find(key);
    return at == std::string::npos ? NAN : std::stod(text.substr(at + key.size()));
  };
  auto table = [](const std::filesystem::path& path) { return read_csv(path).numbers(); };
  // (scenes under studies/; the annulus is a curved Gmsh mesh whose cells are all eliminated apart;
  // elasticity: the square clamped on one side (one of its 3 parts floats), the ring held by
  // rollers; Dirichlet data lift the load, assembled whole and shared out, the others' by each
  // rank's cells)
  const auto scenes = scratch("solve_mpi_scenes");
  std::ofstream(scenes / "dirichlet_data.toml") << paper_scene_with({{"domain.n_x", "12"},
                                                                     {"domain.n_y", "12"},
                                                                     {"boundary.u_D", "\"0.1 * (1 + x)\""},
                                                                     {"contact_mesh.ratio", "\"1/2\""},
                                                                     {"discretization.p", "3"},
                                                                     {"discretization.pC", "1"},
                                                                     {"data.f", "\"-1\""},
                                                                     {"data.g", "\"-x^2\""},
                                                                     {"data.s", std::nullopt}});
  const std::vector<std::pair<std::string, std::string>> cases{
      {HPCONTACT_SOURCE_DIR "/studies/paper/figure1_signorini", "signorini,infsup"},
      {HPCONTACT_SOURCE_DIR "/studies/paper/figure6_friction_s", "friction_s"},
      {HPCONTACT_SOURCE_DIR "/studies/curved/annulus", "signorini,infsup"},
      {HPCONTACT_SOURCE_DIR "/studies/elasticity/square", "frictionless,infsup"},
      {HPCONTACT_SOURCE_DIR "/studies/curved/ring", "frictionless"},
      {(scenes / "dirichlet_data").string(), "signorini"}};
  // (the last: the ring without its rigid motions in BDDC's coarse space, which elastic scenes
  // add by default as PETSc's near null space)
  const std::vector<std::pair<int, std::string>> launches{
      {2, "substructuring"}, {3, "bddc"}, {2, "mumps"}, {3, "bddc -bddc_pc_bddc_use_nnsp 0"}};
  for (const auto& [scene, effects] : cases) {
    const auto dir = scratch("solve_mpi_" + scene.substr(scene.rfind('/') + 1));
    const std::string arguments = " solve " + scene + ".toml --effects " + effects;
    const auto serial = run_command(env + HPCONTACT_CLI + arguments + " --out " + (dir / "serial").string());
    ASSERT_EQ(serial.exit_code, 0) << serial.output;
    for (const auto& [ranks, solver] : launches) {
      if (solver.find("nnsp") != std::string::npos && scene.find("ring") == std::string::npos) continue;
      const std::string launch = "mpirun -n " + std::to_string(ranks) + " --distributed-solver " + solver;
      const auto parallel =
          run_command(env + "mpirun -n " + std::to_string(ranks) + " --oversubscribe " HPCONTACT_CLI + arguments +
                      " --distributed-solver " + solver + " --out " + (dir / "parallel").string());
      ASSERT_EQ(parallel.exit_code, 0) << scene << ", " << launch << "\n" << parallel.output;
      EXPECT_NE(parallel.output.find("on " + std::to_string(ranks) + " ranks"), std::string::npos) << parallel.output;
      const double energy = number_after(serial.output, "energy = ");
      EXPECT_NEAR(number_after(parallel.output, "energy = "), energy, 1e-10 * std::abs(energy)) << parallel.output;
      if (effects.find("infsup") != std::string::npos) {
        const double alpha = number_after(serial.output, "alpha = ");
        EXPECT_GT(alpha, 0.1);
        EXPECT_NEAR(number_after(parallel.output, "alpha = "), alpha, 1e-10) << parallel.output;
      }
      // BDDC's iterations: told the fields and the natural boundary, CG on the elastic square
      // needs at most 16 iterations per solve on 3 ranks without the near null space, 13 with it
      // (45 without either hint: a part floats); the ring without the near null space 24.
      if (solver.starts_with("bddc")) {
        std::ifstream file(dir / "parallel" / "summary.json");
        const auto operators = nlohmann::json::parse(file)["operators"];
        int factors = 0;
        for (const auto& record : operators)
          if (record.contains("iterations")) {
            ++factors;
            EXPECT_LE(record["iterations"]["most"].get<int>(), 30) << scene << ", " << record["name"];
          }
        EXPECT_GE(factors, 1) << scene << ": no factor reported its iterations in " << operators.dump();
      }
      const std::string problem = effects.substr(0, effects.find(','));
      const auto a = table(dir / "serial" / ("boundary_" + problem + ".csv"));
      const auto b = table(dir / "parallel" / ("boundary_" + problem + ".csv"));
      ASSERT_EQ(a.size(), b.size());
      ASSERT_GT(a.size(), 100u);
      // A column that vanishes up to round-off (the ring's tangential displacement and gap) is
      // measured against the table's largest entry.
      double table_scale = 0.0;
      for (const auto& row : a)
        for (double value : row) table_scale = std::max(table_scale, std::abs(value));
      for (std::size_t column = 0; column < a.front().size(); ++column) {
        double scale = 1e-6 * table_scale, difference = 0.0;
        for (std::size_t row = 0; row < a.size(); ++row) {
          scale = std::max(scale, std::abs(a[row][column]));
          difference = std::max(difference, std::abs(a[row][column] - b[row][column]));
        }
        EXPECT_LE(difference, 1e-8 * scale) << scene << " column " << column << " (" << launch << ")";
      }
    }
  }
}

// Under mpirun a scene's whole mesh is freed once its operators hold each rank's part (kept only
// for the extension norm's references): the effects read after that (α's mode, the convergence
// levels, each freeing its own mesh) must still give the serial files, scalar and elastic.
TEST(Cli, SolveUnderMpirunGivesEveryEffectOfTheSerialRunWithoutTheWholeMesh) {
  const std::string env = "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ";
  const auto dir = scratch("solve_mpi_effects");
  const std::string scalar =
      "[domain]\nn_x = 6\nn_y = 6\n[boundary]\ncontact = \"abs(y + 1) < 1e-9\"\n"
      "dirichlet = \"abs(y - 1) < 1e-9\"\n[contact_mesh]\nratio = \"1/2\"\n[discretization]\np = 2\npC = 1\n"
      "[data]\nf = \"-1\"\ng = \"-x^2\"\n[convergence]\nrefinements = 2\n"
      "[run]\neffects = [\"signorini\", \"infsup\", \"convergence\"]\n";
  std::ofstream(dir / "interp.toml") << scalar;
  std::ofstream(dir / "extension.toml") << scalar << "[infsup]\nnorm = \"extension\"\n";
  std::ofstream(dir / "elastic.toml")
      << "[domain]\nn_x = 6\nn_y = 6\n[boundary]\ncontact = \"abs(y + 1) < 1e-9\"\n"
         "dirichlet = \"abs(y - 1) < 1e-9\"\n[contact_mesh]\nratio = 1\n[discretization]\np = 2\npC = 1\n"
         "[material]\nE = \"1\"\nnu = \"0.3\"\n[data]\nf_y = \"-1\"\ng = \"0.05 + 0.2 * x^2\"\n"
         "[convergence]\nrefinements = 2\n[run]\neffects = [\"frictionless\", \"infsup\", \"convergence\"]\n";
  for (const char* name : {"interp", "extension", "elastic"}) {
    const std::string arguments = std::string(" solve ") + (dir / name).string() + ".toml --out ";
    const auto serial = run_command(env + HPCONTACT_CLI + arguments + (dir / name / "serial").string());
    ASSERT_EQ(serial.exit_code, 0) << serial.output;
    const auto parallel = run_command(env + "mpirun -n 2 --oversubscribe " HPCONTACT_CLI + arguments +
                                      (dir / name / "parallel").string());
    ASSERT_EQ(parallel.exit_code, 0) << name << "\n" << parallel.output;
    for (const char* file : {"convergence.csv", "mode.csv"}) {
      // every numeric column but the wall times
      const auto a = read_csv(dir / name / "serial" / file).numeric_columns({"seconds"}),
                 b = read_csv(dir / name / "parallel" / file).numeric_columns({"seconds"});
      ASSERT_GE(a.size(), 4u) << name << ", " << file;
      for (const auto& [column, values] : a) {
        ASSERT_EQ(b.count(column), 1u) << name << ", " << file << ", " << column;
        const auto& other = b.at(column);
        ASSERT_EQ(other.size(), values.size()) << name << ", " << file << ", " << column;
        double scale = 0.0;
        for (double value : values) scale = std::max(scale, std::abs(value));
        for (std::size_t k = 0; k < values.size(); ++k)
          EXPECT_NEAR(other[k], values[k], 1e-8 * scale) << name << ", " << file << ", " << column << " row " << k;
      }
    }
  }
}

// A folder holding an alpha.csv of other columns (an older version's) is refused with a hint;
// --restart replaces it.
TEST(Cli, SweepRefusesAForeignAlphaCsvUnlessRestarted) {
  const auto dir = scratch("sweep_restart");
  std::filesystem::copy_file(HPCONTACT_SOURCE_DIR "/studies/stability/square.toml", dir / "square.toml");
  std::ofstream(dir / "sweep.toml") << "[sweep]\nscene = \"square.toml\"\np = 1\npC = 0\n"
                                       "levels = { \"domain.n_x\" = [4, 8], \"domain.n_y\" = [4, 8] }\n";
  std::filesystem::create_directories(dir / "out");
  std::ofstream(dir / "out" / "alpha.csv") << "problem,norm,p,pC,n,m,alpha\nsignorini,interp,1,0,4,4,0.5\n";
  const std::string command = "sweep " + (dir / "sweep.toml").string() + " --out " + (dir / "out").string();
  const auto refused = run(command);
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("--restart"), std::string::npos) << refused.output;
  const auto restarted = run(command + " --restart");
  ASSERT_EQ(restarted.exit_code, 0) << restarted.output;
  std::ifstream in(dir / "out" / "alpha.csv");
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + 2);  // header + one point per level
  EXPECT_EQ(text.find("problem,norm,p,pC,family,level,"), 0u) << text;
}

// summary.json lists every operator a run built, and a run builds only what its effects need,
// nothing twice: α reuses the coupling of the contact solve; Signorini and (15) share F, B and S;
// Signorini builds no B^s and friction no obstacle functional; without α no A_G factor and no Gram
// matrix; an inf-sup scene assembles no load and solves no contact problem; and no run assembles
// the global K or M (both factors come from element matrices by static condensation).
TEST(Cli, SolveBuildsOnlyTheOperatorsItsEffectsNeedAndNothingTwice) {
  struct Case {
    std::string scene, effects;
    std::map<std::string, int> count;  ///< operator name -> times built (0: never)
  };
  const std::vector<Case> cases{
      {"work_precision/base",
       "infsup",
       {{"S^p(T_h)", 1},
        {"K", 0},
        {"M", 0},
        {"B", 1},
        {"factor(K+M)", 1},
        {"S_G", 1},
        {"G (interpolation norm)", 1},
        {"F", 0},
        {"g", 0},
        {"B^s", 0},
        {"factor(K)", 0},
        {"S", 0},
        {"contact QP (active-set+proximal)", 0}}},
      {"work_precision/base",
       "signorini",
       {{"K", 0},
        {"F", 1},
        {"B", 1},
        {"g", 1},
        {"factor(K)", 1},
        {"S", 1},
        {"contact QP (active-set+proximal)", 1},
        {"M", 0},
        {"B^s", 0},
        {"factor(K+M)", 0},
        {"S_G", 0},
        {"G (interpolation norm)", 0}}},
      {"work_precision/base",
       "friction",
       {{"K", 0}, {"F", 1}, {"B^s", 1}, {"factor(K)", 1}, {"S", 1}, {"B", 0}, {"g", 0}, {"M", 0}, {"S_G", 0}}},
      {"work_precision/base",
       "signorini,friction_s",
       {{"K", 0},
        {"F", 1},
        {"B", 1},
        {"g", 1},
        {"factor(K)", 1},
        {"S", 1},
        {"contact QP (active-set+proximal)", 2},
        {"B^s", 0},
        {"M", 0}}},
      {"work_precision/base",
       "signorini,friction,friction_s,infsup",
       {{"K", 0},
        {"F", 1},
        {"B", 1},
        {"B^s", 1},
        {"g", 1},
        {"factor(K)", 1},
        {"S", 2},
        {"M", 0},
        {"factor(K+M)", 1},
        {"S_G", 1},
        {"G (interpolation norm)", 1}}},
      {"paper/figure4_friction",
       "",  // [infsup] problem = "friction": α of (22) reuses B^s
       {{"K", 0},
        {"F", 1},
        {"B^s", 1},
        {"factor(K)", 1},
        {"S", 1},
        {"M", 0},
        {"factor(K+M)", 1},
        {"S_G", 1},
        {"G (interpolation norm)", 1},
        {"B", 0},
        {"g", 0}}},
  };
  for (const auto& c : cases) {
    const auto dir = scratch("operators");
    std::filesystem::remove_all(dir / "out");
    const auto result = run("solve " + std::string(HPCONTACT_SOURCE_DIR) + "/studies/" + c.scene + ".toml " +
                            (c.effects.empty() ? "" : "--effects " + c.effects) + " --out " + (dir / "out").string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    std::ifstream in(dir / "out" / "summary.json");
    const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto count = [&](const std::string& name) {
      const std::string needle = "\"name\": \"" + name + "\"";
      int n = 0;
      for (auto at = json.find(needle); at != std::string::npos; at = json.find(needle, at + 1)) ++n;
      return n;
    };
    for (const auto& [name, times] : c.count)
      EXPECT_EQ(count(name), times) << c.scene << " " << c.effects << ": " << name;
  }
}

// The convergence effect refines the scene's mesh uniformly and compares every level with the
// finest: energy errors shrink and every level of every problem gets a row.
TEST(Cli, ConvergenceEffectWritesOneRowPerLevelAndProblem) {
  const auto dir = scratch("convergence_effect");
  std::filesystem::remove_all(dir / "out");
  const auto result = run("solve " + std::string(HPCONTACT_SOURCE_DIR) +
                          "/studies/work_precision/base.toml --effects signorini,friction_s,convergence --out " +
                          (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto csv = read_csv(dir / "out" / "convergence.csv");
  EXPECT_EQ(csv.header_line(),
            "problem,level,p,pC,n,m,ndofs,nmult,energy,error_energy,error_lambda,seconds,p_rule,pC_rule");
  std::map<std::string, std::vector<double>> errors;
  for (const auto& cells : csv.rows) {
    const std::string line = line_of(cells);
    ASSERT_EQ(cells.size(), 14u) << line;
    errors[cells[0]].push_back(std::stod(cells[9]));
    // p and pC are numbers whatever the scene writes; p_rule, pC_rule as written.
    EXPECT_EQ(std::to_string(std::stoi(cells[2])), cells[2]) << line;
    EXPECT_EQ(std::to_string(std::stoi(cells[3])), cells[3]) << line;
  }
  ASSERT_EQ(errors.size(), 2u);
  for (const auto& [problem, e] : errors) {
    ASSERT_EQ(e.size(), 4u) << problem;   // the scene's mesh and three refinements (the default)
    EXPECT_EQ(e.back(), 0.0) << problem;  // the finest level is the reference
    EXPECT_GT(e[0], e[1]) << problem;
    EXPECT_GT(e[0], 0.0) << problem;
  }
}

// Not on a terminal (here: a pipe), long runs print a plain progress line at most every
// HPCONTACT_PROGRESS_SECONDS (default 5 s) with the count and the time left; runs shorter than the
// interval stay quiet.
TEST(Cli, ProgressLinesWhenStderrIsNotATerminal) {
  const auto dir = scratch("progress");
  const std::string sweep = std::string(HPCONTACT_SOURCE_DIR) + "/studies/tutorial/sweep.toml";
  const auto every_step = run_command("HPCONTACT_PROGRESS_SECONDS=0 " + std::string(HPCONTACT_CLI) + " sweep " + sweep +
                                      " --out " + (dir / "a").string());
  ASSERT_EQ(every_step.exit_code, 0) << every_step.output;
  EXPECT_NE(every_step.output.find("progress: 1/60 done in "), std::string::npos) << every_step.output;
  EXPECT_NE(every_step.output.find(" s left; next: "), std::string::npos);
  // (An interval longer than the run: the default 5 s could pass under the sanitizers' slowdown.)
  const auto quiet = run_command("HPCONTACT_PROGRESS_SECONDS=1000 " + std::string(HPCONTACT_CLI) + " sweep " + sweep +
                                 " --out " + (dir / "b").string());
  ASSERT_EQ(quiet.exit_code, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("progress: "), std::string::npos) << "a run shorter than the interval prints none";
}

// A point that runs longer than the interval is not silent: a heartbeat line names it and how long
// it has run (here the second point, on 128 x 128 cells at p = 4, against an interval of 0.2 s).
TEST(Cli, ProgressHeartbeatWhileOnePointRuns) {
  const auto dir = scratch("heartbeat");
  std::ofstream(dir / "slow.toml") << "[sweep]\nscene = \"" << HPCONTACT_SOURCE_DIR
                                   << "/studies/stability/square.toml\"\n"
                                      "levels = { \"domain.n_x\" = [4, 128], \"domain.n_y\" = [4, 128] }\n"
                                      "p = 4\npC = 0\nratio = [1]\nnorm = [\"interp\"]\nproblem = [\"signorini\"]\n"
                                      "fit_levels = 2\n";
  const auto run = run_command("HPCONTACT_PROGRESS_SECONDS=0.2 " + std::string(HPCONTACT_CLI) + " sweep " +
                               (dir / "slow.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto at = run.output.find("progress: 1/2 done in ");
  ASSERT_NE(at, std::string::npos) << run.output;
  EXPECT_NE(run.output.find("running for ", at), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("level 2 (domain.n_x=128", at), std::string::npos) << run.output;
}
