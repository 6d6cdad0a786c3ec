#!/usr/bin/env bash
# Contract of `disklab convergence` (verify/convergence.cpp): --quick end to end has every
# (region, strategy, sequence) in its JSON with the documented keys; the same options give the
# same bytes, with one thread or two; bad input exits 2 with one line and writes nothing.
# Usage: bash convergence_contract.sh <path-to-disklab>
set -u
DISKLAB=${1:?usage: convergence_contract.sh <path-to-disklab>}
source "$(dirname "${BASH_SOURCE[0]}")/contract_lib.bash"
export DISKLAB_QUIET=1

"$DISKLAB" convergence --quick --no-plots --out "$TMP/a" >"$TMP/out" 2>"$TMP/err" ||
  fail "--quick exited non-zero: $(tail -3 "$TMP/err")"
"$DISKLAB" convergence --quick --no-plots --threads 1 --out "$TMP/b" >"$TMP/out" 2>"$TMP/err" ||
  fail "--quick --threads 1 exited non-zero: $(tail -3 "$TMP/err")"
"$DISKLAB" convergence --quick --no-plots --threads 2 --out "$TMP/c" >"$TMP/out" 2>"$TMP/err" ||
  fail "--quick --threads 2 exited non-zero: $(tail -3 "$TMP/err")"
for f in convergence.csv convergence.json convergence_fits.csv convergence_references.csv convergence.md; do
  [[ -s $TMP/a/$f ]] || fail "$f missing or empty"
  cmp -s "$TMP/a/$f" "$TMP/b/$f" || fail "$f differs between two runs (default threads vs 1)"
  cmp -s "$TMP/b/$f" "$TMP/c/$f" || fail "$f differs between --threads 1 and --threads 2"
done
leftovers=$(ls -a "$TMP/a" | grep -c '\.tmp' || true)
[[ $leftovers -eq 0 ]] || fail "temporary files left in the output folder"

# The JSON: keys, and every (region, strategy, sequence) the CLI lists, at every N of --quick.
strategies=$("$DISKLAB" convergence --help | sed -n 's/.*--strategies.*default all)://p' | head -1)
sequences=$("$DISKLAB" convergence --help | sed -n 's/.*--sequences.*default all)://p' | head -1)
[[ -n $strategies && -n $sequences ]] || fail "--help does not list the strategies and sequences"
/usr/bin/python3 - "$TMP/a/convergence.json" "$strategies" "$sequences" <<'EOF' || fail "JSON check failed"
import json, sys
j = json.load(open(sys.argv[1]))
strategies, sequences = sys.argv[2].split(), sys.argv[3].split()
regions = ["lit-axis", "lit-off", "penumbra"]
ns = [16, 32, 64, 128, 256, 512, 1024]
bad = []
for key in ("rows", "fits", "references"):
    if key not in j:
        bad.append("missing key " + key)
rows = {(r["region"], r["strategy"], r["sequence"], r["n"]) for r in j["rows"]}
fits = {(f["region"], f["strategy"], f["sequence"]) for f in j["fits"]}
for region in regions:
    for st in strategies:
        for q in sequences:
            if (region, st, q) not in fits:
                bad.append("no fit for %s/%s/%s" % (region, st, q))
            for n in ns:
                if (region, st, q, n) not in rows:
                    bad.append("no row %s/%s/%s/%d" % (region, st, q, n))
for r in j["rows"]:
    if set(r) != {"region", "strategy", "sequence", "n", "rmse", "rel_rmse"} or not r["rmse"] > 0:
        bad.append("bad row %r" % r)
        break
for f in j["fits"]:
    if not {"region", "strategy", "sequence", "slope", "slope_se"} <= set(f):
        bad.append("bad fit %r" % f)
        break
refs = j["references"]
if len(refs) != 48:
    bad.append("expected 48 references, got %d" % len(refs))
for r in refs:
    if set(r) - {"method"} != {"region", "x", "y", "E", "error_estimate"}:
        bad.append("bad reference %r" % r)
        break
    if not (r["E"] > 0 and 0 <= r["error_estimate"] <= 1e-12 * r["E"]):
        bad.append("reference error estimate above 1e-12 relative: %r" % r)
verdicts = {c["verdict"] for c in j.get("claims", [])}
if not verdicts <= {"reproduced", "roughly", "differs", "not measured"} or not verdicts:
    bad.append("claims missing or with unknown verdicts: %r" % verdicts)
if bad:
    print("\n".join(bad[:10]), file=sys.stderr)
    sys.exit(1)
EOF
grep -q "## The memo's claims" "$TMP/a/convergence.md" || fail "convergence.md has no claims table"

# A different first seed gives different numbers (the seed is really used).
"$DISKLAB" convergence --quick --no-plots --seed 7 --regions lit-axis --strategies polar \
  --sequences random --out "$TMP/d" >"$TMP/out" 2>"$TMP/err" || fail "--seed 7 run failed"
"$DISKLAB" convergence --quick --no-plots --seed 8 --regions lit-axis --strategies polar \
  --sequences random --out "$TMP/e" >"$TMP/out" 2>"$TMP/err" || fail "--seed 8 run failed"
cmp -s "$TMP/d/convergence.csv" "$TMP/e/convergence.csv" && fail "--seed 7 and --seed 8 gave the same rows"

# Bad input: exit 2, one line, nothing written (the output folder is not even created).
for args in "--strategies polar,nope" "--sequences sobol" "--max-n 1000" "--min-n 12" \
  "--seeds 0" "--seeds -3" "--fit-min 4096" "--regions dark" "--seed -1" "--seed x" \
  "--threads -1" "--strategies polar,polar"; do
  # shellcheck disable=SC2086
  expect_usage_error convergence --quick --no-plots --out "$TMP/bad" $args
  [[ -e $TMP/bad ]] && { fail "'$args' created the output folder"; rm -rf "$TMP/bad"; }
done
touch "$TMP/file"
expect_usage_error convergence --quick --no-plots --out "$TMP/file"

# --help teaches: the files and their columns.
run convergence --help
for word in convergence.csv convergence.json rel_rmse slope_se error_estimate --quick Examples; do
  [[ $OUT == *"$word"* ]] || fail "--help does not mention $word"
done

if [[ $failures -ne 0 ]]; then
  echo "convergence_contract: $failures failure(s)" >&2
  exit 1
fi
echo "convergence_contract: ok"
