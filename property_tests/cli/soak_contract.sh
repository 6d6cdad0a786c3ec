#!/usr/bin/env bash
# Contract of `disklab soak` (verify/soak.cpp): a short run over random scenes and every map
# finds no contract violation, prints every count, gives the same counts with 1 and 2 threads,
# and rejects bad input with one error line.
# Usage: bash soak_contract.sh <path-to-disklab>
set -u
DISKLAB=${1:?usage: soak_contract.sh <path-to-disklab>}
source "$(dirname "${BASH_SOURCE[0]}")/contract_lib.bash"

OMP_NUM_THREADS=2 DISKLAB_QUIET=1 run soak --samples 400000 --seed 17
[[ $RC -eq 0 ]] || fail "soak found violations (exit $RC): $OUT $ERR"
for key in samples valid scenes invalid_maps "non-finite field" "direction not unit" \
  "direction misses the disk" "pdf(direction) differs from the sample's pdf" "inverse failed" \
  "pdf not positive"; do
  grep -q "^$key" "$TMP/out" || fail "soak output lacks '$key'"
done
two=$OUT
OMP_NUM_THREADS=1 DISKLAB_QUIET=1 run soak --samples 400000 --seed 17
[[ $OUT == "$two" ]] || fail "soak counts differ between 1 and 2 threads"
OMP_NUM_THREADS=2 DISKLAB_QUIET=1 run soak --samples 400000 --seed 18
[[ $OUT != "$two" ]] || fail "soak: another seed gave the same counts (is the seed used?)"

expect_usage_error soak --samples 0
expect_usage_error soak --samples -5
expect_usage_error soak --samples 0x10
expect_usage_error soak --seed ''
expect_usage_error soak --per-scene 0

[[ $failures -eq 0 ]] || { echo "$failures failure(s)" >&2; exit 1; }
echo "soak contract: ok"
