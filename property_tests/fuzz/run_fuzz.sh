#!/usr/bin/env bash
# Runs one libFuzzer harness for a bounded time: first every input of the committed seed corpus
# (the regressions, crashes found earlier included), then new inputs for SECONDS. New corpus
# entries and crash artifacts go to WORK (the build tree), never into the source tree; a finding
# makes the test fail and leaves its input in WORK/artifacts/ (copy it into corpus/<name>/ to keep
# it as a regression). -seed=1 makes every run try the same inputs, so CI does not flake; explore
# with other seeds and longer runs by hand.
# Usage: run_fuzz.sh BINARY CORPUS WORK SECONDS
set -eu
bin=$1 corpus=$2 work=$3 seconds=$4
mkdir -p "$work/new" "$work/artifacts"
exec "$bin" -seed=1 -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/new" "$corpus"
