#!/usr/bin/env bash
# One-command set-up and run on Debian 12: installs the missing Debian packages (apt-get, through
# sudo when not root), configures and builds with CMake (Release, build/), then runs
#   study    the main job: the studies (convergence, stability, the paper's §7 figures, work-precision,
#            curved boundaries, hp-adaptivity, elasticity), writing CSV and PNG into results/ only
#   figures  the same, then copies the pictures and tables the docs show from results/ into
#            studies/ (the committed ones; for developers)
#   test   a formatting check (.clang-format), the GoogleTest suite through CTest; then the same
#          suite built with clang under
#          AddressSanitizer + UndefinedBehaviorSanitizer (build-sanitize/), and the scene fuzzer
#          (libFuzzer) for 60 s from its seed corpus
# Idempotent: a second call installs nothing and rebuilds only what changed.
set -euo pipefail

usage() { echo "usage: bash cmake/quickstart.sh study|figures|test" >&2; exit 2; }
[ $# -eq 1 ] || usage
mode=$1
case "$mode" in study|figures|test) ;; *) usage ;; esac

# Each stage ends with its wall time on stderr (docs/testing.md lists what is slow and why).
stage_start=$SECONDS
stage_done() { echo "quickstart: $1 in $(( SECONDS - stage_start )) s" >&2; stage_start=$SECONDS; }
# A section of the main job: "== what" on stderr, the previous section's time before it.
section_name=""
section() { [ -z "$section_name" ] || stage_done "$section_name"; section_name=$1; echo "== $1" >&2; }

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)

# 1. Debian packages (the only source of dependencies; nothing is downloaded otherwise).
packages=(build-essential cmake pkg-config libeigen3-dev petsc-dev slepc-dev libgsl-dev
          libmuparser-dev libcli11-dev libtomlplusplus-dev libfmt-dev nlohmann-json3-dev
          libsuitesparse-dev libptscotch-dev libgtest-dev libgmock-dev libbenchmark-dev python3-matplotlib
          clang libclang-rt-14-dev clang-format libopenblas0-pthread openmpi-bin libgmsh-dev gmsh
          pybind11-dev python3-dev python3-numpy python3-pytest python3-meshio python3-vtk9)
missing=()
for package in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "quickstart: installing ${missing[*]}" >&2
  sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "quickstart: not root and no sudo: install ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
  fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# 2. The test command first checks the formatting against the committed .clang-format (clang-format
#    from Debian); `clang-format -i` on the files it names fixes them.
if [ "$mode" = test ]; then
  mapfile -t sources < <(find lib tools tests -name '*.cpp' -o -name '*.hpp' | sort)
  clang-format --dry-run --Werror "${sources[@]}" || {
    echo "quickstart: these files differ from .clang-format; run: clang-format -i <file>" >&2; exit 1; }
fi

stage_done "packages and formatting check"

# 3. Configure (once) and build.
if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
fi
cmake --build build -j "$jobs"
stage_done "Release build (build/)"

# 4. Run.
if [ "$mode" = test ]; then
  (cd build && ctest --output-on-failure -j "$jobs")
  stage_done "Release tests"
  # 5. The sanitizer build and the fuzzer. LeakSanitizer is off: OpenMPI (under PETSc/SLEPc)
  #    unloads its components at exit and leaves allocations that LSan cannot attribute.
  export ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  if [ ! -f build-sanitize/CMakeCache.txt ]; then
    CC=clang CXX=clang++ cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DHPCONTACT_SANITIZE=ON -DHPCONTACT_FUZZ=ON
  fi
  cmake --build build-sanitize -j "$jobs"
  stage_done "sanitizer build (build-sanitize/)"
  (cd build-sanitize && ctest --output-on-failure -j "$jobs")
  stage_done "sanitizer tests"
  exec bash tests/fuzz/run_fuzzer.sh build-sanitize/bin/fuzz_scene 60
fi

python=""
for candidate in /usr/bin/python3 python3; do
  if "$candidate" -c "import matplotlib" 2>/dev/null; then python=$candidate; break; fi
done
[ -n "$python" ] || { echo "quickstart: no python3 with matplotlib (install python3-matplotlib)" >&2; exit 1; }

# The main job writes only under results/; `figures` also refreshes the committed copies.
publish() { if [ "$mode" = figures ]; then cp "$1" "$2"; fi; }
mkdir -p results
section "convergence study: studies/convergence/study.toml -> results/convergence"
build/bin/hpcontact convergence studies/convergence/study.toml --out results/convergence
"$python" plots/plot_convergence.py results/convergence
publish results/convergence/convergence.png studies/convergence/convergence.png
section "convergence on a curved domain: studies/curved/convergence.toml -> results/curved"
build/bin/hpcontact convergence studies/curved/convergence.toml --out results/curved
"$python" plots/plot_curved.py results/curved
publish results/curved/curved.png studies/curved/curved.png

section "stability sweep: studies/stability/quick.toml -> results/stability"
build/bin/hpcontact sweep studies/stability/quick.toml --out results/stability --restart
# Spurious modes of the paper's Figure 2 and 3 pairings (and the stable neighbours) at n = 24.
for pairing in "1 0 1" "1 0 1/2" "2 1 1" "3 2 1" "3 2 1/2" "3 1 1"; do
  set -- $pairing
  build/bin/hpcontact infsup --p "$1" --pc "$2" --n 24 --ratio "$3" \
    --mode "results/stability/mode_p$1_pC$2_hH${3//\//-}.csv" > /dev/null
done
"$python" plots/plot_stability.py results/stability
for picture in stable_map alpha_vs_h alpha_vs_pi modes; do
  publish "results/stability/$picture.png" "studies/stability/$picture.png"
done
section "full stability grid: studies/stability/study.toml -> results/stability_full"
build/bin/hpcontact sweep studies/stability/study.toml --out results/stability_full --restart
publish results/stability_full/verdicts.csv studies/stability/verdicts_full.csv
section "stability on geometric meshes: studies/stability/graded*.toml -> results/stability_graded*"
for study in graded graded_anisotropic; do
  build/bin/hpcontact sweep "studies/stability/$study.toml" --out "results/stability_$study" --restart
  "$python" plots/plot_stability.py "results/stability_$study"
  publish "results/stability_$study/alpha_vs_h.png" "studies/stability/${study}_alpha_vs_h.png"
done
section "contact problems of Figures 1, 4, 6: studies/paper/*.toml -> results/paper"
for figure in figure1_signorini figure4_friction figure6_friction_s; do
  build/bin/hpcontact solve "studies/paper/$figure.toml" --out "results/paper/$figure"
  "$python" plots/plot_paper.py "results/paper/$figure"
  publish "results/paper/$figure/figure_${figure#*_}.png" "studies/paper/$figure.png"
done
section "multiplier panels of Figures 2, 3, 5, 7 -> results/paper/panels"
for problem in signorini friction friction_s; do
  case $problem in
    signorini) scene=figure1_signorini; pairings=("1 0 1" "1 0 1/2" "2 1 1" "3 2 1" "3 2 1/2" "3 1 1") ;;
    friction) scene=figure4_friction; pairings=("1 0 1" "1 0 1/2" "2 1 1" "3 2 1" "3 2 1/2" "3 1 1") ;;
    friction_s) scene=figure6_friction_s; pairings=("1 0 1" "1 0 1/2" "2 1 1" "3 2 1" "3 2 1/2" "3 1 1") ;;
  esac
  for pairing in "${pairings[@]}"; do
    set -- $pairing
    build/bin/hpcontact solve "studies/paper/$scene.toml" --p "$1" --pc "$2" --ratio "$3" --effects "$problem" \
      --out "results/paper/panels/${problem}_p$1_pC$2_hH${3//\//-}" > /dev/null
  done
done
"$python" plots/plot_panels.py results/paper/panels
for problem in signorini friction friction_s; do
  publish "results/paper/panels/panels_$problem.png" "studies/paper/panels_$problem.png"
done
section "work-precision study: studies/work_precision/study.toml -> results/work_precision"
build/bin/hpcontact work-precision studies/work_precision/study.toml --out results/work_precision
"$python" plots/plot_work_precision.py results/work_precision
publish results/work_precision/work_precision.png studies/work_precision/work_precision.png
publish results/work_precision/cheapest.csv studies/work_precision/cheapest.csv
publish results/work_precision/reference.csv studies/work_precision/reference.csv
section "hp-adaptivity of (9) from a uniform 4 x 4 start: studies/adaptive/signorini.toml -> results/adaptive"
build/bin/hpcontact solve studies/adaptive/signorini.toml --out results/adaptive/signorini
"$python" plots/plot_adaptive.py results/adaptive/signorini results/work_precision/cheapest.csv
publish results/adaptive/signorini/adaptive.png studies/adaptive/signorini.png
publish results/adaptive/signorini/adapt.csv studies/adaptive/signorini_adapt.csv
section "hp-adaptivity of elastic Hertz without grading points: studies/adaptive/hertz.toml -> results/adaptive"
build/bin/hpcontact solve studies/adaptive/hertz.toml --out results/adaptive/hertz
"$python" plots/plot_adaptive.py results/adaptive/hertz --at 0.2992,-0.01 --width 0.04
publish results/adaptive/hertz/adaptive.png studies/adaptive/hertz.png
publish results/adaptive/hertz/adapt.csv studies/adaptive/hertz_adapt.csv
section "Hertz validation of the elastic contact solver: studies/elasticity/hertz_study.toml -> results/hertz"
build/bin/hpcontact hertz studies/elasticity/hertz_study.toml --out results/hertz
"$python" plots/plot_hertz.py results/hertz
publish results/hertz/hertz.png studies/elasticity/hertz.png
section "elastic stability sweep: studies/elasticity/stability.toml -> results/elastic_stability"
build/bin/hpcontact sweep studies/elasticity/stability.toml --out results/elastic_stability --restart
"$python" plots/plot_stability.py results/elastic_stability
publish results/elastic_stability/stable_map.png studies/elasticity/stable_map.png
publish results/elastic_stability/stable_map_friction_interp.png studies/elasticity/stable_map_friction.png
section "3-D stability sweep: studies/three_d/stability.toml -> results/stability3d"
build/bin/hpcontact sweep studies/three_d/stability.toml --out results/stability3d --restart
"$python" plots/plot_stability.py results/stability3d
publish results/stability3d/stable_map.png studies/three_d/stable_map.png
publish results/stability3d/alpha_vs_h.png studies/three_d/alpha_vs_h.png
# Spurious modes of 3-D pairings on the cube: the unstable p = 1, p_C = 0 at H = h and its stable neighbour (n = 16),
# and the unstable p = 3, p_C = 2 at H = h (n = 8).
for pairing in "1 0 1 16" "1 0 1/2 16" "3 2 1 8"; do
  set -- $pairing
  build/bin/hpcontact infsup --scene studies/three_d/cube.toml --p "$1" --pc "$2" --ratio "$3" \
    --set "domain.n_x=$4" --set "domain.n_y=$4" --set "domain.n_z=$4" \
    --mode "results/stability3d/mode_p$1_pC$2_hH${3//\//-}.vtu" > /dev/null
done
"$python" plots/three_d_mode.py results/stability3d/modes3d.png \
  "p = 1, pC = 0, h/H = 1=results/stability3d/mode_p1_pC0_hH1.vtu" \
  "p = 1, pC = 0, h/H = 1/2=results/stability3d/mode_p1_pC0_hH1-2.vtu" \
  "p = 3, pC = 2, h/H = 1 (n = 8)=results/stability3d/mode_p3_pC2_hH1.vtu"
publish results/stability3d/modes3d.png studies/three_d/modes3d.png
section "two bodies: studies/two_bodies/{stability,families}.toml -> results/two_body_*"
for study in stability families; do
  build/bin/hpcontact sweep "studies/two_bodies/$study.toml" --out "results/two_body_$study" --restart
  "$python" plots/plot_stability.py "results/two_body_$study"
done
publish results/two_body_stability/stable_map.png studies/two_bodies/stable_map.png
publish results/two_body_families/stable_map.png studies/two_bodies/families_map.png
section "local α predictor against the global α: every sweep above and studies/stability/predictor -> results/predictor_check"
for study in stability/predictor/perturbed stability/predictor/gmsh_triangles stability/predictor/curved \
  stability/predictor/degree_rules triangles/stability stability/friction; do
  build/bin/hpcontact sweep "studies/$study.toml" --out "results/predictor_sweep_${study//\//_}" --restart
done
"$python" plots/plot_predictor_check.py results/predictor_check results/stability results/stability_full \
  results/stability_graded results/stability_graded_anisotropic results/elastic_stability results/two_body_stability \
  results/two_body_families results/predictor_sweep_*
publish results/predictor_check/predictor_check.png studies/stability/predictor/predictor_check.png
publish results/predictor_check/predictor_check.csv studies/stability/predictor/predictor_check.csv
stage_done "$section_name"
echo "quickstart: done; CSV and PNG in results/" >&2
