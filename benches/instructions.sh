#!/usr/bin/env bash
# Instructions per iteration of one criterion benchmark, counted by valgrind's callgrind: a
# load-independent complement to the wall-clock medians on a shared machine.
#
#   benches/instructions.sh BENCH_TARGET FILTER      # e.g. builders 'builders/lispsm$'
#
# Runs the bench binary in criterion's --profile-time mode under callgrind and divides the
# inclusive instruction count of criterion's timing loop by the number of calls the loop made to
# the benchmarked function (the largest "(Nx)" call count out of the loop). Only meaningful when
# the benchmarked function is a real call (not inlined into the loop): true of the builders, the
# measurement and the sweep; the #[inline] closed forms are fully inlined, use wall-clock there.
set -euo pipefail
cd "$(dirname "$0")/.."
bench=$1 filter=$2
out=$(mktemp -d)
# Line tables so callgrind attributes inlined code to files; a separate target dir so the
# ordinary bench build is not invalidated (under $CARGO_TARGET_DIR when set, else target/).
export CARGO_PROFILE_BENCH_DEBUG=line-tables-only CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target}/prof"
exe=$(cargo bench --bench "$bench" ${FEATURES:+--features "$FEATURES"} --no-run --message-format=json 2>/dev/null |
  python3 -c 'import json,sys
for l in sys.stdin:
    m=json.loads(l)
    if m.get("reason")=="compiler-artifact" and m.get("executable") and m["target"]["kind"]==["bench"]:
        print(m["executable"])')
valgrind --tool=callgrind --callgrind-out-file="$out/cg" "$exe" --bench --profile-time 1 "$filter" >/dev/null 2>&1
callgrind_annotate --inclusive=yes --tree=caller "$out/cg" | python3 -c '
import re, sys
total, calls = None, 0
for line in sys.stdin:
    m = re.match(r"\s*([\d,]+) \(.*\)\s+\*\s+\S*bencher\.rs:criterion::bencher::Bencher<M>::iter", line)
    if m and total is None:
        total = int(m.group(1).replace(",", ""))
    m = re.match(r"\s*[\d,]+ \(.*\)\s+<\s+\S*benches/\S*Bencher<M>::iter \(([\d,]+)x\)", line)
    if m:
        calls = max(calls, int(m.group(1).replace(",", "")))
if total and calls:
    print(f"{total / calls:.0f} instructions per iteration ({calls} iterations)")
else:
    sys.exit("could not find the timing loop or its call count")
'
rm -r "$out"
