#!/usr/bin/env bash
# Usage: fuzz/run.sh SECONDS [TARGET...]
# Builds every fuzz target (release, with debug assertions and the crate's `invariants`
# feature) and runs each named target (default: all) for SECONDS with libFuzzer, one
# after the other. Seeds come from fuzz/corpus/<target>/ (read only); libFuzzer grows its
# working corpus in fuzz/corpus-work/<target>/ (gitignored); crashes go to
# fuzz/artifacts/<target>/; full logs to fuzz/logs/<target>.log.
# Prints one summary line per target and exits non-zero if any target crashed.
set -uo pipefail

if [ $# -lt 1 ] || ! [[ $1 =~ ^[0-9]+$ ]]; then
    echo "usage: $0 SECONDS [TARGET...]" >&2
    exit 2
fi
secs=$1
shift
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"

all_targets=(surface_ops rs_vertex_orders contract_split journal_ops quad_ops simplify decimate tasks check check_simplify check_quad check_decimate parse_off parse_obj parse_ply parse_stl parse_any poly_weld c_abi)
if [ $# -gt 0 ]; then targets=("$@"); else targets=("${all_targets[@]}"); fi

export RUSTC_BOOTSTRAP=1
# The binaries are looked up below fuzz/target: pin the target dir even when the
# caller's environment points cargo elsewhere.
export CARGO_TARGET_DIR="$here/target"
# Builds all targets (incremental: cheap when nothing changed).
cargo fuzz build -O --debug-assertions 2>logs.build || { cat logs.build >&2; exit 2; }
rm -f logs.build
triple=$(rustc -vV | sed -n 's/^host: //p')
bindir="$here/target/$triple/release"

mkdir -p logs
status=0
summary=()
for t in "${targets[@]}"; do
    mkdir -p "corpus-work/$t" "artifacts/$t" "corpus/$t"
    log="logs/$t.log"
    "$bindir/$t" "corpus-work/$t" "corpus/$t" \
        -max_total_time="$secs" -rss_limit_mb=4096 -timeout=60 -print_final_stats=1 \
        -artifact_prefix="artifacts/$t/" >"$log" 2>&1
    rc=$?
    execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
    [ -n "$execs" ] || execs=$(grep -oE '^#[0-9]+' "$log" | tail -1 | tr -d '#')
    cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+')
    ft=$(grep -oE 'ft: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+')
    corp=$(grep -oE 'corp: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+')
    crashes=$(find "artifacts/$t" -type f \( -name 'crash-*' -o -name 'oom-*' -o -name 'timeout-*' \) | wc -l)
    verdict=ok
    if [ "$rc" -ne 0 ]; then verdict="CRASH(rc=$rc)"; status=1; fi
    line=$(printf '%-22s secs=%s execs=%s cov=%s ft=%s corpus=%s artifacts=%s %s' \
        "$t" "$secs" "${execs:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$crashes" "$verdict")
    echo "$line"
    summary+=("$line")
done
echo "== summary ($(date -u +%Y-%m-%dT%H:%MZ)) =="
printf '%s\n' "${summary[@]}"
exit $status
