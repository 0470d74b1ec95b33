#!/usr/bin/env bash
# A bounded libFuzzer run (ctest: reliability.fuzz.xml, reliability.fuzz.exodus).
# usage: tests/reliability/fuzz.sh SOURCE_DIR FUZZ_BUILD_DIR xml|exodus SECONDS
# Configures (once) tests/reliability/fuzz/ with clang into FUZZ_BUILD_DIR, builds the target
# (-j2), then fuzzes for SECONDS from the committed seeds (tests/reliability/corpus/<target>/),
# keeping what it finds in FUZZ_BUILD_DIR/corpus-<target> (never in the source tree).
# Fails on a crash, an ASan/UBSan report, a leak, a timeout (one input taking longer than
# -timeout) or an exception other than choc::InputError (it aborts the target).
set -uo pipefail
src="$(cd "$1" && pwd)"; mkdir -p "$2"; bdir="$(cd "$2" && pwd)"; target="$3"; secs="$4"
here="$src/tests/reliability"
if [ ! -f "$bdir/Makefile" ]; then  # also after a configure that failed
  cmake -S "$here/fuzz" -B "$bdir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
        > "$bdir.configure.log" 2>&1 || { cat "$bdir.configure.log"; exit 1; }
fi
if ! cmake --build "$bdir" -j "${CHOC_FUZZ_JOBS:-2}" --target "fuzz_$target" > "$bdir/build-$target.log" 2>&1; then
  tail -n 60 "$bdir/build-$target.log"; echo "fuzz: build of fuzz_$target failed"; exit 1
fi
work="$bdir/corpus-$target"; art="$bdir/artifacts-$target"
mkdir -p "$work" "$art"
rm -f "$art"/*  # this run's reproducers only
export TMPDIR="$bdir/tmp"  # the targets' input files (fuzz_input_file.hpp), not /tmp
mkdir -p "$TMPDIR"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$here/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
case "$target" in
  # Teuchos' XML parser is fast: small inputs, 10 s per input is already pathological.
  xml)    opts=(-max_len=8192 -timeout=10) ;;
  # Inputs stay the size of the seeds. choc checks a classic header before netCDF reads it
  # (src/mesh/NetcdfHeader.cpp): without that, a corrupted count or name length made netCDF
  # allocate up to 1.8 GB or loop for tens of seconds. The default limits now hold: any
  # allocation above the 2 GB RSS limit, or an input taking over 10 s, is a finding. The
  # libraries read each input in a child process (src/mesh/ChildProcess.cpp): their crashes
  # there are the expected input errors.
  exodus) opts=(-max_len=8192 -timeout=10) ;;
esac
echo "fuzz: fuzz_$target for $secs s from $here/corpus/$target"
start=$(date +%s)
( cd "$bdir" && "./fuzz_$target" "${opts[@]}" -max_total_time="$secs" -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$art/" "$work" "$here/corpus/$target" ) \
    > "$bdir/fuzz-$target.log" 2>&1
rc=$?
grep -vE "^(NetCDF|Exodus|ERROR: ex_|    exerrval|\[libexodus\]|     )" "$bdir/fuzz-$target.log" | tail -n 40
echo "fuzz: fuzz_$target exit $rc after $(( $(date +%s) - start )) s; corpus $(ls "$work" | wc -l) files"
if [ $rc -ne 0 ]; then
  echo "fuzz: FAILED; reproducer(s) in $art: $(ls -t "$art")"
  echo "fuzz: (the newest is the failure; older ones, if any, come from child processes that" \
       "read a mesh and died there, which choc reports as input errors)"
  echo "fuzz: reproduce with $bdir/fuzz_$target $art/<file>"
  exit 1
fi
echo "fuzz: OK"
