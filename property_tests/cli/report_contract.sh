#!/usr/bin/env bash
# Contract of `disklab report --quick` (verify/report.cpp): every registered part runs and says
# "ok" in index.md, the answer (best strategy x sequence, best map per region) opens it and the
# papers' claims follow, every file the index names exists and is non-empty, PNGs are PNGs (when
# /usr/bin/python3 has matplotlib), a second run into the
# same folder works, and a folder that cannot be created is a usage error (exit 2, one line).
# Usage: bash report_contract.sh <path-to-disklab>
set -u
DISKLAB=${1:?usage: report_contract.sh <path-to-disklab>}
source "$(dirname "${BASH_SOURCE[0]}")/contract_lib.bash"
export DISKLAB_QUIET=1

for round in 1 2; do
  if ! "$DISKLAB" report --quick --out "$TMP/r" >"$TMP/out" 2>"$TMP/err"; then
    fail "round $round: report exited non-zero: $(tail -3 "$TMP/err")"
  fi
done
INDEX=$TMP/r/index.md
[[ -s $INDEX ]] || fail "index.md missing"
for part in accuracy convergence points sequences; do
  grep -q "^## \`$part\`: ok" "$INDEX" || fail "part $part not reported ok in index.md"
done
# The papers' claims come first, with verdicts.
grep -q "^## Claims of the papers, measured here" "$INDEX" || fail "index.md has no claims section"
grep -q "| reproduced |" "$INDEX" || fail "index.md's claims table has no verdicts"
claims_line=$(grep -n "^## Claims of the papers" "$INDEX" | cut -d: -f1)
first_part=$(grep -n '^## `' "$INDEX" | head -1 | cut -d: -f1)
[[ -n $claims_line && -n $first_part && $claims_line -lt $first_part ]] ||
  fail "the claims section is not before the parts"
# The answer opens the index, before the claims: per region the best strategy x sequence
# (convergence) and the best map at equal time (variance), each with a number.
answer_line=$(grep -n "^## The answer" "$INDEX" | cut -d: -f1)
[[ -n $answer_line && -n $claims_line && $answer_line -lt $claims_line ]] ||
  fail "index.md does not open with the answer before the claims"
for region in lit-axis lit-off penumbra; do
  grep -qE "^\| $region \| [a-z0-9-]+ x [a-z0-9-]+ \| [0-9.]+e-[0-9]+ \|" "$INDEX" ||
    fail "the answer has no strategy x sequence row for $region"
done
for region in image near mid far; do
  grep -qE "^\| $region \| [a-z0-9-]+ x [a-z0-9-]+ \| [0-9.]+e[-+][0-9]+ \| [0-9.e+]+ \|" "$INDEX" ||
    fail "the answer has no map row for $region"
done
if grep -q "FAILED" "$INDEX"; then fail "index.md reports a failed part"; fi
# Every linked or embedded file exists and is non-empty.
names=$(grep -o '](\([^)]*\))' "$INDEX" | sed 's/^](\(.*\))$/\1/' | sort -u)
[[ -n $names ]] || fail "index.md links no files"
for f in $names; do
  [[ -s $TMP/r/$f ]] || fail "index.md names $f, which is missing or empty"
done
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  pngs=$(ls "$TMP/r"/*.png 2>/dev/null | wc -l)
  [[ $pngs -ge 3 ]] || fail "expected at least 3 PNGs, found $pngs"
  for p in "$TMP/r"/*.png; do
    [[ $(head -c 4 "$p" | tail -c 3) == PNG ]] || fail "$p is not a PNG"
  done
else
  echo "note: /usr/bin/python3 has no matplotlib; PNG checks skipped" >&2
fi
# Nothing is left half-written (AtomicFile temporaries).
leftovers=$(ls -a "$TMP/r" | grep -c '\.tmp' || true)
[[ $leftovers -eq 0 ]] || fail "temporary files left in the report folder"

touch "$TMP/file"
"$DISKLAB" report --quick --out "$TMP/file/sub" >"$TMP/out" 2>"$TMP/err"
rc=$?
[[ $rc -eq 2 ]] || fail "uncreatable --out: exit $rc, expected 2"
[[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "uncreatable --out: stderr not one line: $(cat "$TMP/err")"

if [[ $failures -ne 0 ]]; then
  echo "report_contract: $failures failure(s)" >&2
  exit 1
fi
echo "report_contract: ok"
