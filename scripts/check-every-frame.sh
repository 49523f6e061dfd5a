#!/usr/bin/env bash
# The every-frame check on the runs of issue 32, longer than the test suite allows: each run's
# every frame ordered (coherently, from the last frame's order) with the oracles and levels
# given, and checked against that frame's own exact ground truth (tests/order/
# check_every_frame.cpp). Prints each run's tally; exits 1 when any frame of any run fails.
#   bash scripts/check-every-frame.sh [quick|issue|walkthrough] [BUILD]     (BUILD: build)
# quick: the power plant's whole walkthrough (900 frames) at scale 0.05, 96x72, every oracle.
# issue: the issue's own runs: the power plant orbiting at 800x600 (CPU oracles; gl at object
#        level), its first 61 walkthrough frames at 800x600 and every tenth of them at 1600x1200
#        (cpu), the bunnies from the issue's camera at 512x512 and a static soup orbiting at
#        512x512 (every oracle).
# walkthrough: the full power plant's 900 walkthrough frames at 320x240 (cpu).
set -uo pipefail
which=${1:-quick}
build=${2:-build}
tool="$build/check_every_frame"
[ -x "$tool" ] || { echo "check-every-frame: no $tool (build the tests first)" >&2; exit 2; }
export LP_NUM_THREADS=0 # Mesa's llvmpipe on the calling thread, as the vissort command sets it
status=0
run() {
  echo "== check_every_frame $*"
  "$tool" "$@" --gtest_brief=1 || status=1
}
case "$which" in
quick)
  run "builtin:powerplant?scale=0.05" --path scene --frames 0:900 --size 96x72 ;;
issue)
  run builtin:powerplant --path orbit --frames 0:2 --size 800x600 --oracles cpu,cpu-reference,exact
  run builtin:powerplant --path orbit --frames 0:2 --size 800x600 --oracles gl --levels object
  run builtin:bunnies --frames 0:6 --size 512x512 --eye 6,4.5,10.5 --target 0,0,0 --fov 45
  run builtin:soup --path orbit --frames 0:4 --size 512x512 --levels triangle
  run builtin:powerplant --path scene --frames 0:61 --size 800x600 --oracles cpu
  run builtin:powerplant --path scene --frames 0:61:10 --size 1600x1200 --oracles cpu ;;
walkthrough)
  run builtin:powerplant --path scene --frames 0:900 --size 320x240 --oracles cpu ;;
*)
  echo "check-every-frame: unknown set '$which' (quick, issue or walkthrough)" >&2; exit 2 ;;
esac
exit $status
