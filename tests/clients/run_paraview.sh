#!/usr/bin/env bash
# ParaView, the real client of Paddy's snapshots (CTest clients.paraview, docs/reliability.md):
#   1. a coarse slump (40 mm spheres, lattice fill, short settling and lift) writes snapshots every 0.1 s;
#   2. pvpython (check_snapshot.py) opens particles.xmf: points, vertex cells, id, radius, velocity
#      and positions equal what Paddy wrote; ParaView's default view of it is not blank;
#      the same series indexed the old way (no connectivity) must fail those checks;
#   3. pvpython (check_snapshot.py --walls) opens walls.xmf: the cone's triangles and vertices as
#      Paddy wrote them, first and last snapshot, lifted (not lowered), visible in the default view;
#   4. the shipped experiments/paraview/show_slump.py renders the last snapshot offscreen to
#      show_slump.png with the cone, which must not be blank.
# The pictures stay in WORK. Fails (never skips) when pvpython, xvfb-run or h5dump is missing.
#   run_paraview.sh PADDY SOURCE_DIR WORK_DIR
set -euo pipefail
paddy=${1:?usage: run_paraview.sh PADDY SOURCE_DIR WORK_DIR}
src=${2:?}
work=${3:?}
here="$(cd "$(dirname "$0")" && pwd)"
fail() { echo "run_paraview: FAIL: $*" >&2; exit 1; }
for tool in pvpython xvfb-run h5dump; do
  command -v "$tool" >/dev/null || fail "$tool is not installed (scripts/install-deps.sh: the clients group)"
done
# Offscreen rendering needs an X server: the whole test runs under one Xvfb. -noreset: by default
# the server resets when its last client disconnects, and pvpython, which connects twice, then
# fails now and then with "bad X server connection".
if [ -z "${PADDY_UNDER_XVFB:-}" ]; then
  PADDY_UNDER_XVFB=1 exec xvfb-run -a -s "-screen 0 1600x1200x24 -noreset" bash "$0" "$@"
fi
pv() { pvpython --force-offscreen-rendering "$@"; }
rm -rf "$work"
mkdir -p "$work"

t0=$(date +%s)
"$paddy" run "$src/experiments/slump.lua" --threads 2 --seed 5 --out "$work/slump" \
  --set particle_diameter=0.04 --set packing=lattice --set settle_max_time=0.3 --set min_rest_time=0.1 --set max_time=0.2 \
  --set snapshot_interval=0.1 --set pictures=false --set progress=false > "$work/slump.log" 2>&1 \
  || { tail -n 30 "$work/slump.log"; fail "the slump run failed"; }
xmf="$work/slump/snapshots/particles.xmf"
[ -s "$xmf" ] || fail "no $xmf"
echo "slump with snapshots: $(( $(date +%s) - t0 )) s, $(ls "$work/slump/snapshots" | grep -c '\.h5$') snapshots"

t0=$(date +%s)
pv "$here/check_snapshot.py" "$xmf" "$work" > "$work/check_snapshot.log" 2>&1 \
  || { cat "$work/check_snapshot.log"; fail "ParaView does not read the snapshots as written"; }
cat "$work/check_snapshot.log"
echo "pvpython checks: $(( $(date +%s) - t0 )) s"

# Control: the same series indexed the old way (Polyvertex without connectivity) must fail the
# cell count and the default-view checks, or the checks above prove nothing.
mkdir -p "$work/old_index"
sed -z 's|NodesPerElement="1">\n *<DataItem[^\n]*/particles/vertex</DataItem>\n *</Topology>|NodesPerElement="1"/>|g' \
  "$xmf" > "$(dirname "$xmf")/old_index.xmf"
grep -q particles/vertex "$(dirname "$xmf")/old_index.xmf" && fail "could not write the old index"
if pv "$here/check_snapshot.py" "$(dirname "$xmf")/old_index.xmf" "$work/old_index" > "$work/old_index.log" 2>&1; then
  fail "the checks pass an index without connectivity (old_index.log)"
fi
grep -q "FAIL: default view .*: 0 pixels show particles" "$work/old_index.log" \
  || { cat "$work/old_index.log"; fail "the old index did not fail on the empty default view"; }
echo "control: the old index (no connectivity) fails: $(grep -c FAIL "$work/old_index.log") checks"

t0=$(date +%s)
walls="$(dirname "$xmf")/walls.xmf"
[ -s "$walls" ] || fail "no $walls: the snapshots hold no cone"
pv "$here/check_snapshot.py" --walls "$walls" "$work" 20 > "$work/check_walls.log" 2>&1 \
  || { cat "$work/check_walls.log"; fail "ParaView does not read the cone (walls.xmf) as written"; }
cat "$work/check_walls.log"
echo "pvpython wall checks: $(( $(date +%s) - t0 )) s"

t0=$(date +%s)
pv "$src/experiments/paraview/show_slump.py" "$xmf" --png "$work/show_slump.png" > "$work/show_slump.log" 2>&1 \
  || { cat "$work/show_slump.log"; fail "show_slump.py failed"; }
cat "$work/show_slump.log"
[ -s "$work/show_slump.png" ] || fail "show_slump.py saved no picture"
grep -Eq "and [1-9][0-9]* wall triangles" "$work/show_slump.log" || fail "show_slump.py drew no cone"
pv "$here/check_snapshot.py" --png-not-blank "$work/show_slump.png" 0.01 || fail "show_slump.png is blank"
echo "show_slump.py: $(( $(date +%s) - t0 )) s; pictures in $work"
