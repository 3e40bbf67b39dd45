#!/usr/bin/env bash
# Install what is missing, build everything (warnings are errors), run every test; then
# rebuild the input-facing tests with AddressSanitizer + UndefinedBehaviorSanitizer and
# run them again.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
JOBS=$(nproc)
BUILD=${BUILD:-build}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DREARM_WERROR=ON -DREARM_SANITIZE=OFF \
  -DREARM_BUILD_TESTS=ON -DREARM_BUILD_BENCH=ON -DREARM_TESTS=
cmake --build "$BUILD" -j"$JOBS"
ctest --test-dir "$BUILD" --no-tests=error --output-on-failure -j"$JOBS"

# The Slurm recipe on a real single-node Slurm (slurm-wlm and munge, started and stopped by the
# script): the smoke sweep as a 3-task job array, merged, equal row for row to the unsharded
# run. About 40 s.
REARM="$BUILD/bin/rearm" bash experiments/slurm/check_local.sh

# Sanitized run of the tests that feed arbitrary input (parser fuzzing, automaton readers,
# the command line, scene and perception input), of the translator's and controller's
# property tests, of the geometry and reactive tests and of the baselines (OMPL, Box2D
# execution), at reduced size (REARM_TEST_SCALE).
ASAN_BUILD=${ASAN_BUILD:-build-asan}
ASAN_TESTS="parser_test;formula_test;bdd_test;letter_set_test;automaton_io_test"
ASAN_TESTS+=";translate_lasso_test;mission_controller_test;mission_property_test;cli_test"
ASAN_TESTS+=";polygon_test;boolean_test;dilation_test;partition_test;distance_test;convex_test"
ASAN_TESTS+=";world_test;sensor_test;semantic_map_test;perception_property_test"
ASAN_TESTS+=";diffeomorphism_test;degenerate_input_test;mapped_space_test;local_freespace_test"
ASAN_TESTS+=";navigation_test"
ASAN_TESTS+=";grasp_test;kinematics_test;closed_loop_test;topology_check_test;topology_property_test"
ASAN_TESTS+=";progress_monitor_test;kinematic_plant_test;interface_layer_test;executive_test;end_to_end_test"
ASAN_TESTS+=";guide_path_test;path_tracker_test;saddle_test;escape_test;fragments_test"
ASAN_TESTS+=";scenario_io_test;convex_pieces_test;sim_world_test;json_writer_test;file_io_test;run_scenario_test"
ASAN_TESTS+=";random_instance_test;motion_query_test;planners_test;executor_test;validator_test"
ASAN_TESTS+=";run_baseline_test;solvability_test;sweep_file_test;sweep_plan_test;trial_log_test"
ASAN_TESTS+=";sweep_runner_test"
# At -O1 (the level the sanitizers' documentation recommends; line tables for their stack
# traces): at -O0, CGAL's uninlined templates made the sanitized tests take 728 s on 2 cores;
# at -O1 they took 370 s after a 958 s build (a CGAL file compiles about 40% slower).
cmake -S . -B "$ASAN_BUILD" -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" \
  -DREARM_SANITIZE=ON -DREARM_WERROR=ON \
  -DREARM_BUILD_TESTS=ON -DREARM_BUILD_BENCH=OFF "-DREARM_TESTS=$ASAN_TESTS"
cmake --build "$ASAN_BUILD" -j"$JOBS"
REARM_TEST_SCALE=0.05 ctest --test-dir "$ASAN_BUILD" --no-tests=error --output-on-failure -j"$JOBS"
