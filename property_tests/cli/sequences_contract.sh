#!/usr/bin/env bash
# Contract of `disklab sequences` (verify/sequences.cpp): the discrepancy table in md/csv/json,
# one row per registered sequence in registry order, values consistent across formats and runs,
# stratified sequences well below random, and bad input -> exit 2 with one stderr line and
# nothing left in --out.
# Usage: bash sequences_contract.sh <path-to-disklab>
set -u
DISKLAB=${1:?usage: sequences_contract.sh <path-to-disklab>}
source "$(dirname "${BASH_SOURCE[0]}")/contract_lib.bash"
export DISKLAB_QUIET=1

MEMO="random best-candidate halton-rotated halton-scrambled sobol-rotated sobol-xor sobol-owen pmj02 pmj02bn"

# ---- CSV: header, one row per sequence in memo order (art, if registered, may sit in between) ----
run sequences --count 256 --seeds 3 --format csv
[[ $RC -eq 0 ]] || fail "csv: exit $RC: $ERR"
[[ $(head -1 "$TMP/out") == "sequence,count,seeds,mean_l2_star,std_error,min,max,random_rms" ]] ||
  fail "csv header: $(head -1 "$TMP/out")"
cp "$TMP/out" "$TMP/a.csv"
names=$(awk -F, 'NR > 1 && $1 != "art" { printf "%s ", $1 }' "$TMP/a.csv")
[[ "$names" == "$MEMO " ]] || fail "csv sequence order: '$names'"
# Values: count/seeds echoed, min <= mean <= max, random_rms = sqrt(5/(36*256)); random's mean
# within a factor 2 of its RMS; the nets (sobol-xor/owen, pmj02, pmj02bn) below random_rms / 5
# (measured ~1/6.6 at N = 256: D ~ 2.7e-3 vs 0.0233).
awk -F, 'NR > 1 {
    if ($2 != 256 || $3 != 3) { print "count/seeds " $0; bad = 1 }
    if (!($6 <= $4 && $4 <= $7) || $4 <= 0) { print "min/mean/max " $0; bad = 1 }
    rms = sqrt(5 / (36 * 256))
    if ($8 < rms * (1 - 1e-15) || $8 > rms * (1 + 1e-15)) { print "random_rms " $8 " vs " rms; bad = 1 }
    if ($1 == "random" && ($4 > 2 * rms || $4 < rms / 2)) { print "random mean " $0; bad = 1 }
    if (($1 == "sobol-xor" || $1 == "sobol-owen" || $1 == "pmj02" || $1 == "pmj02bn") && $4 * 5 > rms) {
      print "net not well below random: " $0; bad = 1 }
  } END { exit bad }' "$TMP/a.csv" >&2 || fail "csv values (see above)"

# Deterministic: same command, same bytes.
run sequences --count 256 --seeds 3 --format csv
cmp -s "$TMP/out" "$TMP/a.csv" || fail "csv differs between two identical runs"
# Another first seed gives other values.
run sequences --count 256 --seeds 3 --seed 100 --format csv
cmp -s "$TMP/out" "$TMP/a.csv" && fail "--seed 100 gives the same table as --seed 1"

# ---- Subset, Markdown and JSON agree with the CSV ----
run sequences --count 256 --seeds 3 --sequences sobol-owen,random
[[ $RC -eq 0 ]] || fail "md subset: exit $RC: $ERR"
rows=$(grep -c '^| [a-z]' "$TMP/out")
[[ $rows -eq 3 ]] || fail "md subset: $rows table rows (header + 2 expected)"
grep -q '^| sobol-owen |' "$TMP/out" && grep -q '^| random |' "$TMP/out" || fail "md subset rows"
first=$(grep '^| [a-z]' "$TMP/out" | sed -n 2p | cut -d'|' -f2 | tr -d ' ')
[[ $first == sobol-owen ]] || fail "md subset keeps the requested order, got '$first' first"

run sequences --count 256 --seeds 3 --format json --out "$TMP/t.json"
[[ $RC -eq 0 && ! -s $TMP/out ]] || fail "json --out: exit $RC, stdout not empty: $ERR"
python3 - "$TMP/t.json" "$TMP/a.csv" <<'PY' || fail "json vs csv"
import csv, json, sys
j = json.load(open(sys.argv[1]))
rows = {r["sequence"]: r for r in csv.DictReader(open(sys.argv[2]))}
assert j["count"] == 256 and j["seeds"] == 3, j
assert [s["name"] for s in j["sequences"]] == list(rows), "order"
for s in j["sequences"]:
    assert s["mean_l2_star"] == float(rows[s["name"]]["mean_l2_star"]), s
PY

# ---- Bad input: exit 2, one line, nothing in --out ----
expect_usage_error sequences --count 0
expect_usage_error sequences --count 65537
expect_usage_error sequences --count abc
expect_usage_error sequences --count
expect_usage_error sequences --seeds 0
expect_usage_error sequences --seeds 1001
expect_usage_error sequences --format xml
expect_usage_error sequences --sequences nope
expect_usage_error sequences --sequences sobol-owen,
expect_usage_error sequences --seed -1
expect_usage_error sequences --seed 1x
expect_usage_error sequences --out "$TMP/missing/dir/t.csv"
expect_usage_error sequences --count 16 --format bad --out "$TMP/bad.csv"
[[ -e $TMP/bad.csv ]] && fail "--out file created on a usage error"

# --help has examples.
run sequences --help
[[ $RC -eq 0 ]] && grep -q "Examples:" "$TMP/out" || fail "--help lacks examples"

if [[ $failures -gt 0 ]]; then
  echo "sequences_contract: $failures failure(s)" >&2
  exit 1
fi
echo "sequences_contract: ok"
