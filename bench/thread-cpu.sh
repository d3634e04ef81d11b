#!/usr/bin/env bash
# Runs a command and prints the CPU time its threads used, grouped by thread name: for a JVM the
# render threads, the JIT compilers, the garbage collector, the compiling thread, the main thread.
# What a whole run costs besides the render, and where (docs/benchmarks.md, section 47).
#
#   bench/thread-cpu.sh [--every SECONDS] COMMAND [ARGS...]
#
# The threads' user + system CPU is read from /proc/PID/task/*/stat every SECONDS (default 0.2)
# until the command exits; a thread keeps the last value read, so one that ends between two
# readings loses at most that interval (its share is then a little low). The command's own
# output goes to stderr. Linux only. Example (this build on drops.crt of CRT 2015, f05acbf's jar):
#   bench/thread-cpu.sh ./crt render -q --sampler grid --assets DIR -o /tmp/a.png drops.crt
#   bench/thread-cpu.sh java -Dcrt.assets=DIR -jar f05acbf.jar render -q -o /tmp/b.png drops.crt
set -euo pipefail

every=0.2
usage() { sed -n '2,13p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --every) every="$2"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    --) shift; break ;;
    -*) echo "thread-cpu: unknown option '$1'" >&2; usage >&2; exit 2 ;;
    *) break ;;
  esac
done
if [ $# -eq 0 ]; then echo "thread-cpu: no command given" >&2; usage >&2; exit 2; fi
if [ ! -d /proc/self/task ]; then echo "thread-cpu: needs Linux's /proc" >&2; exit 3; fi

snaps="$(mktemp)"
trap 'rm -f "$snaps"' EXIT
"$@" >&2 &
pid=$!
while kill -0 "$pid" 2>/dev/null; do
  # Every thread's stat line, copied as it is: one process a reading (on two cores a process per
  # thread would take a share of the machine it measures); a thread that ended meanwhile is skipped.
  cat /proc/"$pid"/task/*/stat >>"$snaps" 2>/dev/null || true
  sleep "$every"
done
status=0
wait "$pid" || status=$?

# The last reading of each thread: its id, its name (field 2, in parentheses, may hold spaces) and
# its user + system clock ticks (fields 14 and 15), summed by name without its number
# ("crt-render-3", "C2 CompilerThread1" and "GC Thread#0" become "crt-render-", "C2 CompilerThread",
# "GC Thread").
awk -v hz="$(getconf CLK_TCK)" '
  { op = index($0, "("); cl = 0
    for (i = length($0); i > 0; i--) if (substr($0, i, 1) == ")") { cl = i; break }
    split(substr($0, cl + 2), f, " ")
    last[$1] = f[12] + f[13]; name[$1] = substr($0, op + 1, cl - op - 1) }
  END {
    for (t in last) { n = name[t]; sub(/[#0-9]+$/, "", n); sum[n] += last[t]; all += last[t] }
    for (n in sum) if (sum[n] > 0) printf "%9.2f s  %s\n", sum[n] / hz, n
    printf "%9.2f s  (all threads)\n", all / hz
  }' "$snaps" | sort -rn
exit "$status"
