#!/usr/bin/env bash
# Contract of `disklab map` for the planar strategies (verify/map.cpp): output format, values,
# round trips, and exit code 2 with one stderr line for bad input.
# Usage: bash map_contract.sh <path-to-disklab>
set -u
DISKLAB=${1:?usage: map_contract.sh <path-to-disklab>}
source "$(dirname "${BASH_SOURCE[0]}")/contract_lib.bash"

# Numbers must agree to 1e-15 absolute: the maps are accurate to a few ulps (see
# property_tests/disk/maps_test.cpp); the CLI only formats them with %.17g.
close() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-15) }'; }

expect_point() {  # "x y" line, expected x, expected y, label
  read -r x y extra <<<"$1"
  if [[ -n ${extra:-} ]] || ! close "$x" "$2" || ! close "$y" "$3"; then
    fail "$4: got '$1', expected '$2 $3'"
  fi
}

# ---- forward values ----
run map --strategy polar --uv 0.25,0
[[ $RC -eq 0 ]] || fail "polar forward exit $RC: $ERR"
expect_point "$OUT" 0.5 0 "polar u=1/4 v=0 (r = sqrt(u))"
run map --strategy polar --uv 1,0.25
expect_point "$OUT" 0 1 "polar u=1 v=1/4"
run map --strategy concentric --uv 0.5,0.5
expect_point "$OUT" 0 0 "concentric centre"
run map --strategy concentric --uv 1,0.5
expect_point "$OUT" 1 0 "concentric right edge midpoint"
run map --strategy concentric --uv 0,0
expect_point "$OUT" -0.70710678118654757 -0.70710678118654757 "concentric corner"

# polar4 / concentric4: four lines, each an exact quarter turn of the previous one.
for s in polar4 concentric4; do
  run map --strategy "$s" --uv 0.3,0.7
  n=$(wc -l <"$TMP/out")
  [[ $RC -eq 0 && $n -eq 4 ]] || { fail "$s: expected 4 lines, got $n (exit $RC)"; continue; }
  mapfile -t L <"$TMP/out"
  for k in 1 2 3; do
    read -r px py <<<"${L[$((k - 1))]}"
    read -r qx qy <<<"${L[$k]}"
    # (x, y) -> (-y, x), exactly
    awk -v px="$px" -v py="$py" -v qx="$qx" -v qy="$qy" 'BEGIN { exit !(qx == -py && qy == px) }' ||
      fail "$s: line $((k + 1)) '${L[$k]}' is not line $k '${L[$((k - 1))]}' rotated by 90 degrees"
  done
  read -r x0 y0 <<<"${L[0]}"
  awk -v x="$x0" -v y="$y0" 'BEGIN { exit !(x >= 0 && y >= 0) }' || fail "$s: copy 0 not in quadrant 0: ${L[0]}"
done
run map --strategy polar4 --uv 0.25,0
expect_point "$(head -1 "$TMP/out")" 0.5 0 "polar4 copy 0 (memo Appendix A: phi = (pi/2) v)"

# pad-zero: "x y weight"; rejection: "x y" or "rejected".
run map --strategy pad-zero --uv 0.75,0.5
read -r x y w <<<"$OUT"
close "$x" 0.5 && close "$y" 0 && close "$w" 1.2732395447351628 || fail "pad-zero inside: '$OUT'"
run map --strategy pad-zero --uv 0,1
read -r x y w <<<"$OUT"
close "$x" -1 && close "$y" 1 && [[ $w == 0 ]] || fail "pad-zero outside (weight 0): '$OUT'"
run map --strategy rejection --uv 0,1
[[ $RC -eq 0 && $OUT == "rejected" ]] || fail "rejection of a corner: exit $RC '$OUT'"
run map --strategy rejection --uv 0.75,0.5
expect_point "$OUT" 0.5 0 "rejection accepted"

# ---- inverse, round trips and the centre ----
run map --strategy polar --inverse --xy 0,0
expect_point "$OUT" 0 0 "polar inverse of the centre"
run map --strategy concentric --inverse --xy 0,0
expect_point "$OUT" 0.5 0.5 "concentric inverse of the centre"
run map --strategy pad-zero --inverse --xy -1,1
expect_point "$OUT" 0 1 "pad-zero inverse of a padding corner"
for s in polar concentric polar4 concentric4 rejection pad-zero; do
  for uv in 0.3,0.7 0.9,0.1 0.5,0.5 0.999,0.001; do
    run map --strategy "$s" --uv "$uv"
    [[ $OUT == rejected ]] && continue
    read -r x y _ <<<"$(tail -1 "$TMP/out")"
    run map --strategy "$s" --inverse --xy "$x,$y"
    [[ $RC -eq 0 ]] || { fail "$s inverse of $x,$y: exit $RC: $ERR"; continue; }
    read -r u v <<<"$OUT"
    # polar4/concentric4: the last line is copy 3; its inverse is the same square point.
    close "$u" "${uv%,*}" && close "$v" "${uv#*,}" || fail "$s round trip $uv -> $x,$y -> $OUT"
  done
done

# ---- bad input: exit 2, one line on stderr, nothing on stdout ----
expect_usage_error map --strategy polar --uv 1.5,0
expect_usage_error map --strategy polar --uv -0.1,0.5
expect_usage_error map --strategy polar --uv 0.5,1.0000001
expect_usage_error map --strategy polar --uv nan,0.5
expect_usage_error map --strategy polar --uv inf,0.5
expect_usage_error map --strategy polar --uv 0.5
expect_usage_error map --strategy polar --uv 0.5,0.5,0.5
expect_usage_error map --strategy polar --uv abc,0.5
expect_usage_error map --strategy polar --uv
expect_usage_error map --strategy polar
expect_usage_error map --strategy polar5 --uv 0.5,0.5
expect_usage_error map --uv 0.5,0.5
expect_usage_error map --strategy polar --xy 0.1,0.1
expect_usage_error map --strategy polar --inverse --uv 0.5,0.5
expect_usage_error map --strategy polar --inverse --xy 0.8,0.8
expect_usage_error map --strategy concentric --inverse --xy nan,0
expect_usage_error map --strategy pad-zero --inverse --xy 1.5,0
expect_usage_error map --strategy polar --uv 0.5,0.5 --bogus
expect_usage_error map --strategy polar5 --uv 0.5,0.5
[[ $ERR == *"polar5"* && $ERR == *"polar4"* ]] || fail "unknown strategy message should name it and list the valid ones: $ERR"

# ---- help with examples ----
run map --help
[[ $RC -eq 0 && $OUT == *"Examples:"* && $OUT == *"--strategy"* ]] || fail "map --help lacks examples (exit $RC)"

if [[ $failures -gt 0 ]]; then
  echo "map_contract: $failures failure(s)" >&2
  exit 1
fi
echo "map_contract: ok"
