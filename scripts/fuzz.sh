#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang, address + undefined sanitizers) in build-fuzz and runs
# each for SECONDS on its corpus, then prints per target the executions, coverage (cov/ft of
# libFuzzer's final statistics) and findings (crashes, hangs over 1 s, leaks, memory over the RSS
# limit), each saved under build-fuzz/findings/TARGET/.
#
# Usage: scripts/fuzz.sh SECONDS [TARGET...]     (targets: map image rosyaml cec scenario roughset campaign store cli)
# Environment: PRIDE_FUZZ_BUILD (build folder, default build-fuzz), PRIDE_FUZZ_JOBS (targets run at
# once, default 1), PRIDE_FUZZ_RSS_MB (default 1024), PRIDE_DATA (the public data of others, for
# extra seeds when set), PRIDE_FUZZ_MAX_LEN (largest input, default 16384 bytes).
# Exit status 1 when any target found something.
#
# Seeds: fuzz/corpus/TARGET/ (checked in) plus, collected at run time, the maps and scenarios of
# examples/maps and PRIDE_DATA/movingai, nav2's maps of PRIDE_DATA/ros, the CSV tables of
# PRIDE_DATA/roughset and the campaign files of examples/campaigns. New inputs libFuzzer finds go to build-fuzz/corpus/TARGET/ (kept
# between runs, so later runs start where earlier ones stopped).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
seconds=${1:?usage: scripts/fuzz.sh SECONDS [TARGET...]}
shift
all=(map image rosyaml cec scenario roughset campaign store cli)
targets=("$@")
((${#targets[@]})) || targets=("${all[@]}")
build=${PRIDE_FUZZ_BUILD:-build-fuzz}
jobs=${PRIDE_FUZZ_JOBS:-1}
rss=${PRIDE_FUZZ_RSS_MB:-1024}
# Inputs up to 16 KiB (and seeds no larger): every format's structure fits, and one input stays far
# below the 1 s hang limit even on a loaded machine (a 37 KB map took 0.5 s there under ASan).
max_len=${PRIDE_FUZZ_MAX_LEN:-16384}
data=${PRIDE_DATA:-}

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -O1 with assertions kept (no -DNDEBUG): what sanitizers and fuzzers are usually built with.
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DPRIDE_FUZZ=ON -DPRIDE_BUILD_TESTS=OFF -DPRIDE_BUILD_BENCH=OFF \
  -DPRIDE_MPI=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j "${PRIDE_FUZZ_BUILD_JOBS:-2}" --target "${targets[@]/#/fuzz_}"

# The seeds of one target, gathered into build/seeds/TARGET (files up to max_len only).
collect() {
  local t=$1 len=$2 dir="$build/seeds/$1"
  rm -rf "$dir"
  mkdir -p "$dir" "$build/corpus/$t"
  [[ -d fuzz/corpus/$t ]] && cp fuzz/corpus/"$t"/* "$dir"/ 2>/dev/null || true
  local f
  case $t in
    map) for f in examples/maps/*.map ${data:+"$data"/movingai/*.map}; do [[ -f $f ]] && cp "$f" "$dir/"; done ;;
    rosyaml) for f in ${data:+"$data"/ros/*.yaml}; do [[ -f $f ]] && cp "$f" "$dir/"; done ;;
    scenario) for f in examples/maps/*.scen ${data:+"$data"/movingai/*.scen}; do [[ -f $f ]] && cp "$f" "$dir/"; done ;;
    roughset) for f in ${data:+"$data"/roughset/*.csv}; do [[ -f $f ]] && cp "$f" "$dir/"; done ;;
    campaign) for f in examples/campaigns/*.toml; do cp "$f" "$dir/"; done ;;
  esac
  find "$dir" -type f -size +"$((len / 1024))"k -delete
}

# Inputs up to max_len, but stores are SQLite files of several 4 KiB pages, and a map YAML reaches
# past the 64 KiB bound of its reader.
target_len() {
  case $1 in store) echo 65536 ;; rosyaml) echo 70000 ;; *) echo "$max_len" ;; esac
}

# One target for `seconds` in all. A timeout on a loaded machine may be the process waiting for a
# core, not a hang: the input is run again alone, and when it then takes under a second the
# session is restarted for the time left (the input is kept under findings-load/, not counted).
run_one() {
  local t=$1 len
  len=$(target_len "$t")
  rm -rf "$build/findings/$t" "$build/findings-load/$t" "$build/logs/$t".*
  mkdir -p "$build/findings/$t" "$build/findings-load/$t" "$build/logs"
  collect "$t" "$len"
  local deadline=$(($(date +%s) + seconds)) session=0 status=0
  while :; do
    local left=$((deadline - $(date +%s)))
    ((left > 0)) || break
    session=$((session + 1))
    status=0
    # Hangs: -timeout=1 (seconds per input); memory: -rss_limit_mb (and malloc_limit_mb with it);
    # leaks: -detect_leaks=1, checked after every input that allocated more than it freed.
    ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:symbolize=1} \
    UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
      nice "$build/fuzz/fuzz_$t" "$build/corpus/$t" "$build/seeds/$t" -max_total_time="$left" -timeout=1 \
      -max_len="$len" -rss_limit_mb="$rss" -detect_leaks=1 -print_final_stats=1 \
      -artifact_prefix="$build/findings/$t/" >"$build/logs/$t.$session.log" 2>&1 || status=$?
    ((status != 0)) || break
    local found
    found=$(find "$build/findings/$t" -type f)
    [[ $(wc -l <<<"$found") == 1 && $(basename "$found") == timeout-* ]] || break
    # Run alone, an input that fails (a crash, a leak the timeout cut short) is a finding as it is.
    local ms alone=0
    "$build/fuzz/fuzz_$t" "$found" >"$build/logs/$t.alone.log" 2>&1 || alone=$?
    ((alone == 0)) || break
    ms=$(sed -n 's/^Executed .* in \([0-9]*\) ms$/\1/p' "$build/logs/$t.alone.log")
    [[ -n $ms ]] && ((ms < 1000)) || break
    rm -f "$build/logs/$t.alone.log"
    # Out of the corpus too, or the next session times out again loading it.
    local sum
    sum=$(basename "$found")
    sum=${sum#timeout-}
    rm -f "$build/corpus/$t/$sum"
    find "$build/seeds/$t" -type f -exec sha1sum {} + | awk -v s="$sum" '$1 == s {print $2}' | xargs -r rm -f
    mv "$found" "$build/findings-load/$t/"
    status=0
  done
  echo "$status" >"$build/logs/$t.status"
}

running=0
for t in "${targets[@]}"; do
  run_one "$t" &
  running=$((running + 1))
  if ((running >= jobs)); then
    wait -n || true
    running=$((running - 1))
  fi
done
wait

found=0
printf '%-10s %12s %8s %8s %10s %8s  %s\n' target executions cov ft corpus sessions findings
for t in "${targets[@]}"; do
  logs=("$build/logs/$t".[0-9]*.log)
  execs=$(cat "${logs[@]}" 2>/dev/null | sed -n 's/^stat::number_of_executed_units: \([0-9]*\)/\1/p' | awk '{n += $1} END {print n}')
  # The largest coverage any session reached (a session cut short by the time left may end
  # before it has reloaded the whole corpus), and the corpus as the last line left it.
  stats=$(cat "${logs[@]}" 2>/dev/null | grep -aE '^#[0-9]+.* cov: ' || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$stats" | sort -n | tail -1)
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$stats" | sort -n | tail -1)
  corpus=$(ls -v "${logs[@]}" 2>/dev/null | tail -1 | xargs -r grep -aE '^#[0-9]+.* cov: ' | tail -1 |
    sed -n 's/.* corp: \([0-9]*\/[0-9a-zA-Z]*\).*/\1/p' || true)
  n=$(find "$build/findings/$t" -type f | wc -l)
  what=$(find "$build/findings/$t" -type f -printf '%f ' | head -c 300)
  load=$(find "$build/findings-load/$t" -type f | wc -l)
  # No status: the target's loop stopped before its end, which is a failure too.
  status=$(cat "$build/logs/$t.status" 2>/dev/null || echo "unknown (the target's loop stopped early)")
  if ((n > 0)) || [[ $status != 0 ]]; then
    found=1
    [[ -n $what ]] || what="exit status $status, see $build/logs/$t.*.log"
    [[ -f $build/logs/$t.alone.log ]] && what+=" (the input run alone: $build/logs/$t.alone.log)"
  fi
  printf '%-10s %12s %8s %8s %10s %8s  %s\n' "$t" "${execs:-?}" "${cov:-?}" "${ft:-?}" "${corpus:-?}" "${#logs[@]}" \
    "${what:-none}$( ((load)) && echo " ($load timeouts under load, under 1 s when run alone)")"
done
exit "$found"
