#!/usr/bin/env bash
# The sanitizer step of `make test` (ctest: reliability.sanitize).
# usage: tests/reliability/sanitize.sh SOURCE_DIR ASAN_BUILD_DIR
# Configures (once) and builds ASAN_BUILD_DIR with -DCHOC_SANITIZE=ON (ASan + UBSan), only the
# targets needed, with -j2; then runs the unit tests of input, mesh, fem, reference, output,
# contact and analysis and a shortened SDNL111 B (tests/reliability/inputs/sdnl111b_short.xml),
# the sliding block, and the compact block with friction (condensed pressures, then explicit)
# with leak detection on and UBSan halting on the first error. Fails on any sanitizer report.
# An existing ASAN_BUILD_DIR is reused (reconfigured), so a warm run only recompiles what changed.
# Leaks reported at exit inside Open MPI, hwloc and Kokkos are suppressed by
# tests/reliability/lsan.supp (library frames only; see that file).
set -uo pipefail
src="$(cd "$1" && pwd)"; mkdir -p "$2"; bdir="$(cd "$2" && pwd)"
here="$src/tests/reliability"
jobs="${CHOC_SANITIZE_JOBS:-2}"
start=$(date +%s)
stamp() { echo "sanitize: [$(( $(date +%s) - start )) s] $*"; }

# Configure every time (cheap on an existing tree): a reused tree must see new source files.
if true; then
  stamp "configuring $bdir"
  cmake -S "$src" -B "$bdir" -DCHOC_SANITIZE=ON -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1" -DCMAKE_C_FLAGS_RELEASE="-O1 -g1" \
        -DCMAKE_CXX_COMPILER=mpicxx -DCMAKE_C_COMPILER=mpicc > "$bdir.configure.log" 2>&1 ||
    { cat "$bdir.configure.log"; echo "sanitize: configure failed"; exit 1; }
fi
modules=(input mesh fem reference output contact analysis)
targets=(choc)
for m in "${modules[@]}"; do targets+=("unit_$m"); done
# The build runs the test executables only to list their tests (gtest_discover_tests): that is
# not a test run, so leaks at exit are not checked there (they are in the runs below).
export ASAN_OPTIONS="detect_leaks=0"
stamp "building ${targets[*]} (-j$jobs)"
if ! cmake --build "$bdir" -j "$jobs" --target "${targets[@]}" > "$bdir/asan-build.log" 2>&1; then
  tail -n 60 "$bdir/asan-build.log"; echo "sanitize: build failed"; exit 1
fi
stamp "built"

export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=0"
# use_tls=0: LeakSanitizer does not scan threads' dynamic TLS for roots. GCC 12's scan crashed
# ("Tracer caught signal 11", "LeakSanitizer has encountered a fatal error") at the exit of
# unit_contact, even with no test run, on a DTLS block of an Open MPI component unloaded by
# MPI_Finalize, depending on the binary's layout. Fewer roots can only report more blocks as
# leaked, never hide one (src/ has no thread_local); leak_report still fails on any of choc's.
export LSAN_OPTIONS="suppressions=$here/lsan.supp:print_suppressions=0:use_tls=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export OMPI_MCA_btl="self,vader"  # no network probing under ASan
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
logs="$bdir/sanitize-logs"; rm -rf "$logs"; mkdir -p "$logs"
CHOC_PY=$(command -v /usr/bin/python3 || command -v python3)
failed=()
check_log() {  # name rc log
  # Memory errors and undefined behaviour: any report fails. Leaks: only those with a frame in
  # choc's own code fail (leak_report.py); library-only blocks at exit are listed, not hidden.
  local bad=0
  if grep -qE "ERROR: AddressSanitizer|runtime error:|SUMMARY: (Address|UndefinedBehavior)Sanitizer: [^0-9]" "$3"; then
    bad=1
    grep -nE -A40 "ERROR: AddressSanitizer|runtime error:" "$3" | head -n 120
  fi
  if grep -q "ERROR: LeakSanitizer" "$3"; then
    "$CHOC_PY" "$here/leak_report.py" "$3" "$src" || bad=1
  elif [ "$2" -ne 0 ]; then
    bad=1
  fi
  # A run that failed for another reason (a test failure) also fails.
  if grep -qE "^\[  FAILED  \]" "$3"; then bad=1; fi
  if [ $bad -ne 0 ]; then
    failed+=("$1 (exit $2)")
    echo "---- $1: exit $2"; tail -n 20 "$3"
  fi
}
for m in "${modules[@]}"; do
  exe="$bdir/tests/unit_$m"
  [ -x "$exe" ] || { failed+=("unit_$m (not built)"); continue; }
  # Tests that spawn choc or need several ranks are exercised elsewhere (Mpi* need mpirun).
  ( cd "$bdir/tests" && "$exe" --gtest_filter='-Mpi*' ) > "$logs/unit_$m.log" 2>&1
  rc=$?
  stamp "unit_$m: exit $rc, $(grep -cE '^\[       OK \]' "$logs/unit_$m.log") tests passed"
  check_log "unit_$m" $rc "$logs/unit_$m.log"
done
# run_input NAME HISTORY: choc run inputs/NAME.xml under the sanitizers; it must write HISTORY.
run_input() {
  local out="$logs/$1"
  "$bdir/choc" run "$here/inputs/$1.xml" -o "$out" > "$logs/choc_$1.log" 2>&1
  local rc=$?
  stamp "choc run $1.xml: exit $rc"
  check_log "choc run $1" $rc "$logs/choc_$1.log"
  [ -f "$out/$2" ] || failed+=("choc run $1: no $2")
}
run_input sdnl111b_short cerc_int.history.csv
run_input sliding_short lagrange.history.csv
run_input condensed_friction_short explicit.history.csv
# The suppressions must not hide everything: count what they matched.
stamp "done"
if [ ${#failed[@]} -gt 0 ]; then
  echo "sanitize: FAILED: ${failed[*]} (logs in $logs)"
  exit 1
fi
echo "sanitize: OK (no ASan or UBSan report, no leak in choc's code; logs in $logs)"
