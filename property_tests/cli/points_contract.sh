#!/usr/bin/env bash
# Contract of `disklab points` (verify/points.cpp): CSV columns and values, determinism per
# seed, agreement with `disklab map`, every registered sequence, PNG output, and bad input ->
# exit 2 with one stderr line and nothing (partial or not) left in --out.
# Usage: bash points_contract.sh <path-to-disklab>
set -u
DISKLAB=${1:?usage: points_contract.sh <path-to-disklab>}
source "$(dirname "${BASH_SOURCE[0]}")/contract_lib.bash"
export DISKLAB_QUIET=1

STRATEGIES="pad-zero rejection polar concentric polar4 concentric4"

# ---- CSV shape for every strategy ----
for s in $STRATEGIES; do
  run points --strategy "$s" --sequence random --seed 3 --count 64
  [[ $RC -eq 0 ]] || { fail "$s: exit $RC: $ERR"; continue; }
  [[ $(head -1 "$TMP/out") == "index,u,v,x,y,weight" ]] || fail "$s: header '$(head -1 "$TMP/out")'"
  rows=$(($(wc -l <"$TMP/out") - 1))
  [[ $rows -eq 64 ]] || fail "$s: $rows rows, expected 64"
  # index 0..N-1 in order; u, v in [0,1); disk points inside the unit disk (pad-zero: weight 0
  # exactly for the points outside, 4/pi inside); polar4/concentric4 rows 4k..4k+3 share (u, v).
  awk -F, -v s="$s" 'NR > 1 {
      i = NR - 2
      if ($1 != i) { print s ": index " $1 " on row " i; bad = 1 }
      if ($2 < 0 || $2 >= 1 || $3 < 0 || $3 >= 1) { print s ": uv out of [0,1): " $0; bad = 1 }
      r2 = $4 * $4 + $5 * $5
      if (s == "pad-zero") {
        if (!((r2 <= 1 && $6 == 1.2732395447351628) || (r2 > 1 && $6 == 0))) { print s ": weight " $0; bad = 1 }
      } else {
        if (r2 > 1 + 4e-15 || $6 != 1) { print s ": point/weight " $0; bad = 1 }
      }
      if ((s == "polar4" || s == "concentric4") && i % 4 != 0 && ($2 != pu || $3 != pv)) {
        print s ": row " i " does not reuse the square point of row " i - i % 4; bad = 1
      }
      if (i % 4 == 0) { pu = $2; pv = $3 }
    } END { exit bad }' "$TMP/out" >&2 || fail "$s: CSV values (see above)"
  cp "$TMP/out" "$TMP/$s.csv"
done

# The rows agree with `disklab map` on the same square point.
for s in polar concentric; do
  line=$(sed -n 6p "$TMP/$s.csv")
  IFS=, read -r _ u v x y _ <<<"$line"
  run map --strategy "$s" --uv "$u,$v"
  read -r mx my <<<"$(cat "$TMP/out")"
  [[ $mx == "$x" && $my == "$y" ]] || fail "$s: points row '$line' but map gives '$mx $my'"
done

# Rejection reports what it consumed (stderr, unless DISKLAB_QUIET) and skips outside points.
env -u DISKLAB_QUIET "$DISKLAB" points --strategy rejection --seed 3 --count 64 >/dev/null 2>"$TMP/err"
grep -Eq "rejection used [0-9]+ square points for 64 disk samples" "$TMP/err" ||
  fail "rejection: no consumption note on stderr: $(cat "$TMP/err")"

# ---- square points (no --strategy) and determinism ----
run points --sequence random --seed 5 --count 10
[[ $(head -1 "$TMP/out") == "index,u,v" && $(wc -l <"$TMP/out") -eq 11 ]] || fail "square CSV shape"
cp "$TMP/out" "$TMP/a.csv"
run points --sequence random --seed 5 --count 10
cmp -s "$TMP/out" "$TMP/a.csv" || fail "same seed gave different points"
run points --sequence random --seed 6 --count 10
cmp -s "$TMP/out" "$TMP/a.csv" && fail "different seeds gave the same points"
# The square points are the u,v columns of the mapped CSV (same sequence, same seed).
run points --sequence random --seed 3 --count 64
diff <(tail -n +2 "$TMP/out") <(tail -n +2 "$TMP/polar.csv" | cut -d, -f1-3) >/dev/null ||
  fail "square points differ from the polar CSV's u,v columns"

# ---- every sequence the registry offers works with every strategy ----
run points --sequence no-such-sequence
names=$(sed -n 's/.*(valid: \(.*\))$/\1/p' <<<"$ERR")
[[ -n $names ]] || fail "unknown sequence message does not list the valid names: $ERR"
for q in $names; do
  for s in "" $STRATEGIES; do
    if [[ -n $s ]]; then run points --strategy "$s" --sequence "$q" --seed 1 --count 16
    else run points --sequence "$q" --seed 1 --count 16; fi
    [[ $RC -eq 0 && $(wc -l <"$TMP/out") -eq 17 ]] || fail "sequence $q strategy '${s:-none}': exit $RC $ERR"
  done
done

# ---- --out: same bytes as stdout; PNG ----
run points --strategy polar4 --seed 3 --count 64 --out "$TMP/f.csv"
[[ $RC -eq 0 ]] && cmp -s "$TMP/f.csv" "$TMP/polar4.csv" || fail "--out CSV differs from stdout CSV"
for args in "--strategy polar4" "--strategy pad-zero" ""; do
  rm -f "$TMP/p.png"
  # shellcheck disable=SC2086
  run points $args --seed 2 --count 256 --format png --out "$TMP/p.png"
  [[ $RC -eq 0 ]] || { fail "png '$args': exit $RC: $ERR"; continue; }
  [[ $(head -c 8 "$TMP/p.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
    fail "png '$args': not a PNG file"
done

# ---- bad input: exit 2, one stderr line, and nothing left in --out ----
expect_usage_error points --count 0
expect_usage_error points --count -5
expect_usage_error points --count abc
expect_usage_error points --count
expect_usage_error points --strategy polar5
expect_usage_error points --strategy
expect_usage_error points --sequence no-such-sequence
expect_usage_error points --format jpg
expect_usage_error points --format png
expect_usage_error points --seed -1
expect_usage_error points --seed 1.5
expect_usage_error points --seed 18446744073709551616
expect_usage_error points --count 100000000000
expect_usage_error points --strategy polar --out "$TMP/no/such/folder/x.csv"
touch "$TMP/plainfile"
expect_usage_error points --strategy polar --out "$TMP/plainfile/x.csv"
expect_usage_error points --strategy polar --out "$TMP"
for bad in "--count 0" "--strategy nope" "--sequence nope" "--format nope"; do
  rm -f "$TMP/never.csv"
  # shellcheck disable=SC2086
  expect_usage_error points $bad --out "$TMP/never.csv"
  [[ -e $TMP/never.csv ]] && fail "'$bad': left $TMP/never.csv behind"
done
# A failing run leaves an existing --out untouched, and no temporary files next to it.
echo "precious" >"$TMP/keep.csv"
expect_usage_error points --count 0 --out "$TMP/keep.csv"
[[ $(cat "$TMP/keep.csv") == precious ]] || fail "failed run modified an existing --out"
leftovers=$(find "$TMP" -name '.*tmp*' | wc -l)
[[ $leftovers -eq 0 ]] || fail "temporary files left behind: $(find "$TMP" -name '.*tmp*')"

run points --help
grep -q "Examples:" "$TMP/out" || fail "points --help lacks examples"

if [[ $failures -gt 0 ]]; then
  echo "points_contract: $failures failure(s)" >&2
  exit 1
fi
echo "points_contract: ok"
