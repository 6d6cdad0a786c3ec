#!/usr/bin/env bash
# Contract of `disklab variance` (verify/variance.cpp): --quick end to end writes every file
# with the documented keys and columns (PNGs too when matplotlib is there); the error numbers
# are the same with one thread or two; bad input exits 2 with one line and writes nothing.
# Usage: bash variance_contract.sh <path-to-disklab>
set -u
DISKLAB=${1:?usage: variance_contract.sh <path-to-disklab>}
source "$(dirname "${BASH_SOURCE[0]}")/contract_lib.bash"
export DISKLAB_QUIET=1

"$DISKLAB" variance --quick --out "$TMP/a" >"$TMP/out" 2>"$TMP/err" ||
  fail "--quick exited non-zero: $(tail -3 "$TMP/err")"
for f in variance.csv variance_fits.csv variance_images.csv variance_cost.csv variance_newton.csv \
  variance_references.csv variance.json variance.md variance_reference.f64; do
  [[ -s $TMP/a/$f ]] || fail "$f missing or empty"
done
# 128 x 128 float64.
[[ $(stat -c %s "$TMP/a/variance_reference.f64") -eq $((128 * 128 * 8)) ]] ||
  fail "variance_reference.f64 is not 128 x 128 float64"
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  for f in variance_reference.png variance_images_pmj02.png variance_near.png variance_equal_time.png; do
    [[ -s $TMP/a/$f ]] || fail "$f not written although matplotlib is installed"
  done
fi
leftovers=$(ls -a "$TMP/a" | grep -c '\.tmp' || true)
[[ $leftovers -eq 0 ]] || fail "temporary files left in the output folder"

maps=$("$DISKLAB" variance --help | sed -n 's/.*--maps.*default all): //p' | head -1 | tr ',' ' ')
[[ -n $maps ]] || fail "--help does not list the maps"
/usr/bin/python3 - "$TMP/a/variance.json" "$maps" <<'EOF' || fail "JSON check failed"
import json, sys
j = json.load(open(sys.argv[1]))
maps = sys.argv[2].split()
sequences = ["random", "sobol-owen", "pmj02"]
regions = ["near", "mid", "far"]
ns = [16, 32, 64, 128, 256, 512, 1024]
bad = []
for key in ("rows", "fits", "images", "references", "cost", "claims"):
    if key not in j:
        bad.append("missing key " + key)
rows = {(r["region"], r["map"], r["sequence"], r["n"]) for r in j["rows"]}
fits = {(f["region"], f["map"], f["sequence"]) for f in j["fits"]}
for region in regions:
    for m in maps:
        for q in sequences:
            if (region, m, q) not in fits:
                bad.append("no fit for %s/%s/%s" % (region, m, q))
            for n in ns:
                if (region, m, q, n) not in rows:
                    bad.append("no row %s/%s/%s/%d" % (region, m, q, n))
for r in j["rows"]:
    if set(r) != {"region", "map", "sequence", "n", "rmse", "rel_rmse"} or not r["rmse"] > 0:
        bad.append("bad row %r" % r)
        break
images = {(i["map"], i["sequence"]) for i in j["images"] if i["region"] == "image"}
if not {i["region"] for i in j["images"]} <= {"image", "shadowed"}:
    bad.append("image rows with unknown regions")
for m in maps:
    for q in sequences:
        if (m, q) not in images:
            bad.append("no image row %s/%s" % (m, q))
for i in j["images"]:
    need = {"region", "map", "sequence", "spp", "mse", "rel_mse", "ns_per_sample",
            "ratio_to_baseline", "efficiency"}
    if not need <= set(i) or i["spp"] != 16:
        bad.append("bad image row %r" % i)
        break
    if not (i["mse"] > 0 and i["ns_per_sample"] > 0 and i["efficiency"] > 0):
        bad.append("non-positive image numbers %r" % i)
        break
    if not 0 < i["ratio_to_baseline"] < float("inf"):
        bad.append("image row without a positive cost ratio %r" % i)
        break
# One cost row per map and a last one for the baseline, whose ratio to itself is 1.
cost_maps = [c["map"] for c in j["cost"]]
if cost_maps != list(maps) + ["baseline"]:
    bad.append("cost rows %r, expected the maps then baseline" % cost_maps)
elif j["cost"][-1]["ratio_to_baseline"] != 1:
    bad.append("the baseline's ratio to itself is %r" % j["cost"][-1]["ratio_to_baseline"])
refs = j["references"]
if len(refs) != 48:
    bad.append("expected 48 references, got %d" % len(refs))
for r in refs:
    if not (r["E"] > 0 and 0 <= r["error_estimate"] <= 1e-12 * r["E"]):
        bad.append("reference error estimate above 1e-12 relative: %r" % r)
verdicts = {c["verdict"] for c in j["claims"]}
if not verdicts <= {"reproduced", "roughly", "differs", "not measured"} or not verdicts:
    bad.append("claims missing or with unknown verdicts: %r" % verdicts)
if bad:
    print("\n".join(bad[:10]), file=sys.stderr)
    sys.exit(1)
EOF
grep -q "## The memo's open question: radial4" "$TMP/a/variance.md" || fail "variance.md does not answer the radial4 question"
grep -q "## Claims" "$TMP/a/variance.md" || fail "variance.md has no claims table"

# The error numbers do not depend on the thread count (timings do, so only these files).
small="--quick --no-plots --maps area,radial,radial4,gamito --sequences random,pmj02 --seeds 4 --images 1 --timing-reps 1"
# shellcheck disable=SC2086
"$DISKLAB" variance $small --threads 1 --out "$TMP/b" >"$TMP/out" 2>"$TMP/err" || fail "--threads 1 failed"
# shellcheck disable=SC2086
"$DISKLAB" variance $small --threads 2 --out "$TMP/c" >"$TMP/out" 2>"$TMP/err" || fail "--threads 2 failed"
for f in variance.csv variance_fits.csv variance_references.csv variance_newton.csv variance_reference.f64 \
  variance_image_random.f64; do
  cmp -s "$TMP/b/$f" "$TMP/c/$f" || fail "$f differs between --threads 1 and --threads 2"
done
# A different first seed gives different numbers.
# shellcheck disable=SC2086
"$DISKLAB" variance $small --seed 5 --out "$TMP/d" >"$TMP/out" 2>"$TMP/err" || fail "--seed 5 failed"
cmp -s "$TMP/b/variance.csv" "$TMP/d/variance.csv" && fail "--seed 5 gave the same rows as --seed 0"

# Bad input: exit 2, one line, nothing written (the output folder is not even created).
for args in "--maps radial,nope" "--sequences sobol" "--max-n 1000" "--min-n 8" "--seeds 0" \
  "--images 0" "--timing-reps 0" "--fit-min 4096" "--regions dark" "--seed -1" "--threads -1" \
  "--maps radial,radial" "--max-n 131072"; do
  # shellcheck disable=SC2086
  expect_usage_error variance --quick --no-plots --out "$TMP/bad" $args
  [[ -e $TMP/bad ]] && { fail "'$args' created the output folder"; rm -rf "$TMP/bad"; }
done
touch "$TMP/file"
expect_usage_error variance --quick --no-plots --out "$TMP/file"
expect_usage_error variance --quick --no-plots --out ""

run variance --help
for word in variance.csv variance.json variance_images.csv ns_per_sample ratio_to_baseline efficiency \
  rel_mse slope_se error_estimate newton_mean --quick Examples; do
  [[ $OUT == *"$word"* ]] || fail "--help does not mention $word"
done

if [[ $failures -ne 0 ]]; then
  echo "variance_contract: $failures failure(s)" >&2
  exit 1
fi
echo "variance_contract: ok"
