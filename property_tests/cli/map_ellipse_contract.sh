#!/usr/bin/env bash
# Contract of `disklab map --map NAME` for the spherical-ellipse maps (verify/map.cpp,
# ellipse/any_map.h): output format, unit directions and pdfs (checked against `disklab
# solid-angle` and an independent area-sampling density), forward/inverse round trips, radial4's
# four copies, rejection, and exit code 2 with one stderr line for bad input.
# Usage: bash map_ellipse_contract.sh <path-to-disklab>
set -u
DISKLAB=${1:?usage: map_ellipse_contract.sh <path-to-disklab>}
source "$(dirname "${BASH_SOURCE[0]}")/contract_lib.bash"

# ---- tolerances (one place) ----
# Round trip u -> direction -> u through %.17g text: the maps' own round trip is ~1e-13 or better
# on these moderate scenes (property_tests/ellipse/map_bijectivity_test.cpp); printing the
# direction adds <= 1 ulp per component, amplified by the inverse's conditioning (~1e2 here).
TOL_ROUND_TRIP=1e-12
# pdf * Omega for uniform maps: pdf = 1/Omega is one rounded division of the same Omega that
# `solid-angle` prints (same closed form), so the product is 1 to a couple of ulps.
TOL_UNIFORM=1e-14
# |direction| = 1: a normalized vector printed at %.17g, a few ulps.
TOL_UNIT=1e-15
# area sampling's pdf vs the density recomputed here from the printed direction with awk's
# doubles (distance^2 / (A cos)): both round a few operations, conditioning ~1 on these scenes.
TOL_AREA_PDF=1e-12

# Scenes: on the axis at distance 1, and a tilted disk seen off-axis (the ellipse suites'
# "on-axis-unit" and "tilted-mid").
SCENES=("--center 0,0,1 --normal 0,0,-1 --radius 1 --point 0,0,0"
        "--center 1,0.5,2 --normal 0.3,-0.2,-1 --radius 1 --point 0,0,0")
INVERTIBLE="area parallel radial ld-radial radial4 tabulated radial-fast"
UNIFORM="parallel radial ld-radial radial4 radial-fast"
# Not on a cell edge of the tabulated map (eps1 = j/1024): the proposal's height jumps there
# (bound_j changes from cell to cell), so v is only defined up to which side rounding picks.
UVS="0.3,0.7 0.9,0.1 0.55,0.999 0.1301,0.5 0.7,0.25 0.999,0.6"

# ---- forward format, unit directions, pdfs, round trips ----
for scene in "${SCENES[@]}"; do
  # shellcheck disable=SC2086
  run solid-angle $scene
  omega=$OUT
  [[ $RC -eq 0 ]] || { fail "solid-angle $scene: exit $RC $ERR"; continue; }
  for m in $INVERTIBLE gamito; do
    for uv in $UVS; do
      # shellcheck disable=SC2086
      run map --map "$m" $scene --uv "$uv"
      [[ $RC -eq 0 ]] || { fail "$m $scene --uv $uv: exit $RC: $ERR"; continue; }
      want=1; [[ $m == radial4 ]] && want=4
      n=$(wc -l <"$TMP/out")
      [[ $n -eq $want ]] || fail "$m --uv $uv: $n lines, expected $want: $OUT"
      [[ -s $TMP/err ]] && fail "$m --uv $uv: wrote to stderr: $ERR"
      cp "$TMP/out" "$TMP/fwd"
      first_z=""
      while read -r x y z pdf extra; do
        if [[ $x == rejected ]]; then
          [[ $m == gamito || $m == tabulated ]] || fail "$m --uv $uv: rejected, but $m never rejects"
          continue
        fi
        [[ -z ${extra:-} && -n $pdf ]] || { fail "$m --uv $uv: line is not 'x y z pdf': $x $y $z $pdf $extra"; continue; }
        norm=$(awk -v x="$x" -v y="$y" -v z="$z" 'BEGIN { printf "%.17g", sqrt(x*x + y*y + z*z) }')
        relclose "$norm" 1 $TOL_UNIT || fail "$m --uv $uv: |direction| = $norm"
        awk -v p="$pdf" 'BEGIN { exit !(p > 0) }' || fail "$m --uv $uv: pdf $pdf not positive"
        # radial4: the four copies are reflections (x, y) -> (+-x, +-y) in the ellipse frame, so
        # they share the angle to the axis; with the on-axis scene that is z.
        if [[ $m == radial4 && $scene == *"--center 0,0,1 "* ]]; then
          [[ -z $first_z ]] && first_z=$z
          relclose "$z" "$first_z" 1e-15 || fail "radial4 --uv $uv: copies differ in z: $z vs $first_z"
        fi
        if [[ " $UNIFORM " == *" $m "* ]]; then
          prod=$(awk -v p="$pdf" -v o="$omega" 'BEGIN { printf "%.17g", p * o }')
          relclose "$prod" 1 $TOL_UNIFORM || fail "$m $scene --uv $uv: pdf * Omega = $prod"
        fi
        if [[ $m == gamito ]]; then
          # Proposal pdf 1/S of the circumscribed square's solid angle S > Omega.
          awk -v p="$pdf" -v o="$omega" 'BEGIN { exit !(p * o < 1 && p * o > 0.5) }' ||
            fail "gamito --uv $uv: pdf * Omega = $pdf * $omega not in (0.5, 1)"
          # An accepted candidate hits the disk: area sampling can invert it.
          # shellcheck disable=SC2086
          "$DISKLAB" map --map area $scene --inverse --dir "$x,$y,$z" >/dev/null 2>&1 ||
            fail "gamito --uv $uv: accepted direction $x,$y,$z misses the disk"
          continue
        fi
        if [[ $m == area ]]; then
          # Independent density: hit point t d on the plane (c - o).n = t d.n, p = t^2/(A |d.n|/|n|).
          # shellcheck disable=SC2086
          want_pdf=$(awk -v x="$x" -v y="$y" -v z="$z" -v s="$scene" 'BEGIN {
            n = split(s, w, " "); for (i = 1; i < n; i += 2) v[w[i]] = w[i + 1]
            split(v["--center"], c, ","); split(v["--normal"], nn, ","); split(v["--point"], o, ",")
            r = v["--radius"]; ln = sqrt(nn[1]^2 + nn[2]^2 + nn[3]^2)
            dn = (x * nn[1] + y * nn[2] + z * nn[3]) / ln
            t = ((c[1] - o[1]) * nn[1] + (c[2] - o[2]) * nn[2] + (c[3] - o[3]) * nn[3]) / ln / dn
            if (dn < 0) dn = -dn
            printf "%.17g", t * t / (3.14159265358979323846 * r * r * dn) }')
          relclose "$pdf" "$want_pdf" $TOL_AREA_PDF || fail "area $scene --uv $uv: pdf $pdf, expected $want_pdf"
        fi
        # Round trip through the CLI: the inverse of every copy is the square point used.
        # shellcheck disable=SC2086
        run map --map "$m" $scene --inverse --dir "$x,$y,$z"
        [[ $RC -eq 0 ]] || { fail "$m $scene: inverse of $x,$y,$z: exit $RC: $ERR"; continue; }
        read -r bu bv bextra <<<"$OUT"
        IFS=, read -r u v <<<"$uv"
        if [[ -n ${bextra:-} ]] || ! relclose "$bu" "$u" $TOL_ROUND_TRIP || ! relclose "$bv" "$v" $TOL_ROUND_TRIP; then
          fail "$m $scene: u=($uv) -> ($x, $y, $z) -> '$OUT'"
        fi
        # The inverse takes a direction of any length.
        sx=$(awk -v a="$x" 'BEGIN { printf "%.17g", 3 * a }')
        sy=$(awk -v a="$y" 'BEGIN { printf "%.17g", 3 * a }')
        sz=$(awk -v a="$z" 'BEGIN { printf "%.17g", 3 * a }')
        # shellcheck disable=SC2086
        run map --map "$m" $scene --inverse --dir "$sx,$sy,$sz"
        read -r cu cv <<<"$OUT"
        { relclose "$cu" "$u" $TOL_ROUND_TRIP && relclose "$cv" "$v" $TOL_ROUND_TRIP; } ||
          fail "$m $scene: inverse of 3 * direction gave '$OUT' for u=($uv)"
      done <"$TMP/fwd"
    done
  done
done

# ---- rejection: one candidate, 'rejected' and exit 0 ----
TILTED=${SCENES[1]}
# shellcheck disable=SC2086
run map --map gamito $TILTED --uv 0,0   # the square's corner lies outside the inscribed disk
[[ $RC -eq 0 && $OUT == rejected ]] || fail "gamito at the square's corner: exit $RC, '$OUT'"
# tabulated at v = 1 in the middle of a cell: 1 - h_r decreases across the cell, so the
# proposal's top lies outside the ellipse (eps1 = 0.5 / 1024 with the default 256-cell table).
# shellcheck disable=SC2086
run map --map tabulated $TILTED --uv 0.00048828125,1
[[ $RC -eq 0 && $OUT == rejected ]] || fail "tabulated above the ellipse: exit $RC, '$OUT'"

# ---- bad input: exit 2, one stderr line, nothing on stdout ----
S0=${SCENES[0]}
# shellcheck disable=SC2086
{
  expect_usage_error map --map radial $S0 --uv nan,0.5
  expect_usage_error map --map radial $S0 --uv 0.5,inf
  expect_usage_error map --map radial $S0 --uv 1.5,0.5
  expect_usage_error map --map radial $S0 --uv=-0.1,0.5
  expect_usage_error map --map radial $S0 --uv 0.5
  expect_usage_error map --map radial $S0
  expect_usage_error map --map no-such-map $S0 --uv 0.5,0.5
  expect_usage_error map --map $S0 --uv 0.5,0.5
  expect_usage_error map --map radial --center 0,0,1 --normal 0,0,-1 --point 0,0,0 --uv 0.5,0.5
  expect_usage_error map --map radial --normal 0,0,-1 --radius 1 --point 0,0,0 --uv 0.5,0.5
  expect_usage_error map --map radial --center 0,0,1 --radius 1 --point 0,0,0 --uv 0.5,0.5
  expect_usage_error map --map radial --center 0,0,1 --normal 0,0,-1 --radius 1 --uv 0.5,0.5
  expect_usage_error map --map radial --center 0,0,1 --normal 0,0,-1 --radius=-1 --point 0,0,0 --uv 0.5,0.5
  expect_usage_error map --map radial --center 0,0,1 --normal 0,0,-1 --radius 0 --point 0,0,0 --uv 0.5,0.5
  expect_usage_error map --map radial --center 0,0,1 --normal 0,0,-1 --radius nan --point 0,0,0 --uv 0.5,0.5
  expect_usage_error map --map radial --center 0,0,1 --normal 0,0,0 --radius 1 --point 0,0,0 --uv 0.5,0.5
  expect_usage_error map --map radial --center 0,nan,1 --normal 0,0,-1 --radius 1 --point 0,0,0 --uv 0.5,0.5
  expect_usage_error map --map radial --center 0,0,1 --normal 0,0,-1 --radius 1 --point 0,0 --uv 0.5,0.5
  # Degenerate geometry: behind the one-sided disk, in its plane.
  for m in $INVERTIBLE gamito; do
    expect_usage_error map --map $m --center 0,0,1 --normal 0,0,1 --radius 1 --point 0,0,0 --uv 0.5,0.5
    expect_usage_error map --map $m --center 0,0,0 --normal 0,0,1 --radius 1 --point 3,0,0 --uv 0.5,0.5
    expect_usage_error map --map $m --center 0,0,1 --normal 0,0,1 --radius 1 --point 0,0,0 --inverse --dir 0,0,1
  done
  grep -q "degenerate geometry" "$TMP/err" || fail "degenerate geometry message: $(cat "$TMP/err")"
  # Inverse: direction off the disk, zero, missing, no inverse, wrong input option.
  expect_usage_error map --map radial $S0 --inverse --dir 0,0,-1
  expect_usage_error map --map radial $S0 --inverse --dir 1,0,0.5
  expect_usage_error map --map radial $S0 --inverse --dir 0,0,0
  expect_usage_error map --map radial $S0 --inverse --dir 0,nan,1
  expect_usage_error map --map radial $S0 --inverse
  expect_usage_error map --map radial $S0 --inverse --uv 0.5,0.5
  expect_usage_error map --map radial $S0 --inverse --xy 0.1,0.1
  expect_usage_error map --map radial $S0 --uv 0.5,0.5 --dir 0,0,1
  expect_usage_error map --map gamito $S0 --inverse --dir 0,0,1
  grep -q "no inverse" "$TMP/err" || fail "gamito --inverse message: $(cat "$TMP/err")"
  # --strategy and --map are exclusive; scene options need --map.
  expect_usage_error map --strategy polar --map radial $S0 --uv 0.5,0.5
  expect_usage_error map --strategy polar --radius 1 --uv 0.5,0.5
  expect_usage_error map --center 0,0,1 --uv 0.5,0.5
  expect_usage_error map --strategy polar --inverse --dir 0,0,1
}

# projected: needs --receiver-normal (and only it takes one); its pdf is the cosine over P.
VERT="--center 0,0,0.6 --normal 1,0,0 --radius 0.5 --two-sided --point 0.3,0.1,0"
# shellcheck disable=SC2086
run map --map projected $VERT --receiver-normal 0,0,1 --uv 0.3,0.7
[[ $RC -eq 0 ]] || fail "projected with --receiver-normal: exit $RC ($ERR)"
read -r px py pz ppdf <<<"$OUT"
[[ -n ${ppdf:-} ]] && awk -v z="$pz" -v p="$ppdf" 'BEGIN { exit !(z > 0 && p > 0) }' ||
  fail "projected sample '$OUT': expected a direction above the horizon and a positive pdf"
# shellcheck disable=SC2086
expect_usage_error map --map projected $VERT --uv 0.3,0.7
# shellcheck disable=SC2086
expect_usage_error map --map radial $VERT --receiver-normal 0,0,1 --uv 0.3,0.7
# shellcheck disable=SC2086
expect_usage_error map --map projected $VERT --receiver-normal 0,0,0 --uv 0.3,0.7
# The receiver facing away: nothing above its horizon.
# shellcheck disable=SC2086
expect_usage_error map --map projected --center 0,0,2 --normal 0,0,-1 --radius 1 --point 0,0,0 \
  --receiver-normal 0,0,-1 --uv 0.3,0.7
: "$px" "$py"

run map --help
grep -q "disklab map --map radial" "$TMP/out" || fail "map --help lacks a --map example"

if [[ $failures -ne 0 ]]; then
  echo "map_ellipse_contract: $failures failure(s)" >&2
  exit 1
fi
echo "map_ellipse_contract: ok"
