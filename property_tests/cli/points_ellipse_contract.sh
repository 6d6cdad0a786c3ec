#!/usr/bin/env bash
# Contract of `disklab points --map NAME` (verify/points.cpp): CSV header and row count, rows equal
# to `disklab map` for the same square point, unit directions, radial4's four rows per square
# point, rejected candidates as pdf-0 rows, unbiasedness of the rows as an estimator of Omega,
# determinism, atomic --out, PNG, and exit code 2 with one stderr line for bad input.
# Usage: bash points_ellipse_contract.sh <path-to-disklab>
set -u
DISKLAB=${1:?usage: points_ellipse_contract.sh <path-to-disklab>}
source "$(dirname "${BASH_SOURCE[0]}")/contract_lib.bash"
export DISKLAB_QUIET=1

# ---- tolerances and significance (one place) ----
# |direction| = 1 and pdf * Omega = 1 (uniform maps): a few ulps of %.17g text (see
# map_ellipse_contract.sh).
TOL_UNIT=1e-15
TOL_UNIFORM=1e-14
# Unbiasedness: the mean over N rows of 1/pdf (0 where pdf = 0) estimates Omega. With N = 2^14
# random (iid) rows, the mean's standard error is sd/sqrt(N), estimated from the same rows; a
# 5-sigma bound fails a correct map with probability ~6e-7 per map (8 maps: ~5e-6), while the
# authors' biased gamito (pdf 1/Omega, zeros on rejection) is off by ~21% here, ~50 sigma.
N_MEAN=16384
Z_MEAN=5

SCENE="--center 1,0.5,2 --normal 0.3,-0.2,-1 --radius 1 --point 0,0,0"
MAPS="area gamito parallel radial ld-radial radial4 tabulated radial-fast"
UNIFORM="parallel radial ld-radial radial4 radial-fast"

# shellcheck disable=SC2086
run solid-angle $SCENE
OMEGA=$OUT

for m in $MAPS; do
  # ---- CSV shape and per-row checks ----
  # shellcheck disable=SC2086
  run points --map "$m" $SCENE --sequence sobol-owen --seed 4 --count 64
  [[ $RC -eq 0 ]] || { fail "$m: exit $RC: $ERR"; continue; }
  cp "$TMP/out" "$TMP/$m.csv"
  [[ $(head -1 "$TMP/$m.csv") == "index,u,v,x,y,z,pdf" ]] || fail "$m: header '$(head -1 "$TMP/$m.csv")'"
  [[ $(wc -l <"$TMP/$m.csv") -eq 65 ]] || fail "$m: $(($(wc -l <"$TMP/$m.csv") - 1)) rows, expected 64"
  bad=$(awk -F, -v m="$m" -v om="$OMEGA" -v tu=$TOL_UNIT -v tp=$TOL_UNIFORM -v uni=" $UNIFORM " '
    NR == 1 { next }
    {
      i = NR - 2
      if (NF != 7 || $1 != i) { print "row " NR ": " $0; next }
      if ($7 < 0) { print "negative pdf: " $0; next }
      if ($7 == 0 && m != "gamito" && m != "tabulated") { print "pdf 0 from " m ": " $0; next }
      n = sqrt($4 * $4 + $5 * $5 + $6 * $6); d = n - 1; if (d < 0) d = -d
      if ($7 > 0 && d > tu) { print "|direction| " n ": " $0; next }
      if (index(uni, " " m " ") && (($7 * om - 1) > tp || (1 - $7 * om) > tp)) print "pdf*Omega: " $0
      if (m == "radial4" && i % 4 != 0 && ($2 != pu || $3 != pv)) print "radial4 copy with new u,v: " $0
      if (m == "radial4" && i % 4 == 0 && NR > 2 && $2 == pu && $3 == pv) print "radial4 reused u,v: " $0
      pu = $2; pv = $3
    }' "$TMP/$m.csv")
  [[ -z $bad ]] || fail "$m: $(head -3 <<<"$bad")"

  # Rows agree with `disklab map` for the same square point (copy k for radial4).
  for row in 2 7 12; do
    line=$(sed -n "${row}p" "$TMP/$m.csv")
    IFS=, read -r idx u v x y z pdf <<<"$line"
    # shellcheck disable=SC2086
    run map --map "$m" $SCENE --uv "$u,$v"
    k=0; [[ $m == radial4 ]] && k=$((idx % 4))
    got=$(sed -n "$((k + 1))p" "$TMP/out")
    if [[ $pdf == 0 ]]; then
      [[ $got == rejected ]] || fail "$m row $idx has pdf 0 but map gives '$got'"
    else
      [[ $got == "$x $y $z $pdf" ]] || fail "$m row '$line' but map gives '$got'"
    fi
  done

  # ---- unbiasedness: mean of 1/pdf over all rows (0 where pdf = 0) vs Omega ----
  # shellcheck disable=SC2086
  run points --map "$m" $SCENE --sequence random --seed 11 --count $N_MEAN
  verdict=$(awk -F, -v om="$OMEGA" -v z=$Z_MEAN 'NR > 1 { w = ($7 > 0) ? 1 / $7 : 0; s += w; s2 += w * w; n++ }
    END { mean = s / n; var = s2 / n - mean * mean; if (var < 0) var = 0; se = sqrt(var / n)
          d = mean - om; if (d < 0) d = -d
          printf "%s mean %.10g Omega %.10g se %.3g", (d <= z * se + 1e-13 * om) ? "ok" : "BAD", mean, om, se }' "$TMP/out")
  [[ $verdict == ok* ]] || fail "$m: sum of 1/pdf is biased: $verdict"
done

# Rejection samplers do reject at this scene (gamito: ~1 - pi/4 of the candidates).
rej=$(awk -F, 'NR > 1 && $7 == 0' "$TMP/gamito.csv" | wc -l)
[[ $rej -gt 0 && $rej -lt 32 ]] || fail "gamito: $rej of 64 candidates rejected, expected some (~14)"

# ---- determinism, --out, stdout ----
# shellcheck disable=SC2086
run points --map radial $SCENE --sequence sobol-owen --seed 4 --count 64 --out "$TMP/f.csv"
[[ $RC -eq 0 && -z $OUT ]] && cmp -s "$TMP/f.csv" "$TMP/radial.csv" || fail "--out CSV differs from stdout CSV"
# shellcheck disable=SC2086
run points --map radial $SCENE --sequence sobol-owen --seed 5 --count 64
cmp -s "$TMP/out" "$TMP/radial.csv" && fail "different seeds gave the same rows"
# The u,v columns are the square points of the same sequence (one per row; radial4: per 4 rows).
run points --sequence sobol-owen --seed 4 --count 64
diff <(tail -n +2 "$TMP/out") <(tail -n +2 "$TMP/radial.csv" | cut -d, -f1-3) >/dev/null ||
  fail "radial's u,v columns are not the sequence's points"

# ---- PNG ----
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  for m in radial gamito radial4; do
    rm -f "$TMP/p.png"
    # shellcheck disable=SC2086
    run points --map "$m" $SCENE --count 256 --format png --out "$TMP/p.png"
    [[ $RC -eq 0 ]] || { fail "png $m: exit $RC: $ERR"; continue; }
    [[ $(head -c 8 "$TMP/p.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
      fail "png $m: not a PNG file"
  done
else
  echo "points_ellipse_contract: /usr/bin/python3 has no matplotlib; PNG check skipped" >&2
fi

# ---- bad input: exit 2, one stderr line, nothing left in --out ----
BAD=(
  "--map no-such-map $SCENE"
  "--map radial --center 0,0,1 --normal 0,0,-1 --point 0,0,0"
  "--map radial --center 0,0,1 --normal 0,0,-1 --radius=-1 --point 0,0,0"
  "--map radial --center 0,0,1 --normal 0,0,-1 --radius nan --point 0,0,0"
  "--map radial --center 0,0,1 --normal 0,0,0 --radius 1 --point 0,0,0"
  "--map radial --center nan,0,1 --normal 0,0,-1 --radius 1 --point 0,0,0"
  "--map radial --center 0,0,1 --normal 0,0,1 --radius 1 --point 0,0,0"
  "--map gamito --center 0,0,0 --normal 0,0,1 --radius 1 --point 3,0,0"
  "--map radial $SCENE --count 0"
  "--map radial $SCENE --sequence nope"
  "--map radial $SCENE --format svg"
  "--map radial $SCENE --strategy polar"
  "--strategy polar --center 0,0,1"
  "--radius 1"
)
for args in "${BAD[@]}"; do
  rm -f "$TMP/never.csv"
  # shellcheck disable=SC2086
  expect_usage_error points $args --out "$TMP/never.csv"
  [[ -e $TMP/never.csv ]] && fail "'$args': left $TMP/never.csv behind"
done
echo "precious" >"$TMP/keep.csv"
# shellcheck disable=SC2086
expect_usage_error points --map radial --center 0,0,1 --normal 0,0,1 --radius 1 --point 0,0,0 --out "$TMP/keep.csv"
[[ $(cat "$TMP/keep.csv") == precious ]] || fail "failed run modified an existing --out"
# shellcheck disable=SC2086
expect_usage_error points --map radial $SCENE --format png

run points --help
grep -q "points --map radial" "$TMP/out" || fail "points --help lacks a --map example"
grep -q "pdf 0" "$TMP/out" || fail "points --help does not say how rejections are written"

if [[ $failures -ne 0 ]]; then
  echo "points_ellipse_contract: $failures failure(s)" >&2
  exit 1
fi
echo "points_ellipse_contract: ok"
