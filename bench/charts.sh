#!/usr/bin/env bash
# Draws the charts of docs/benchmarks.md (docs/images/bench-*.png) from the CSV files in
# bench/results, which bench/povray-compare.sh and bench/scaling.sh write.
#
#   bench/charts.sh [RESULTS_DIR [IMAGES_DIR]]
#
# Uses XChart (org.knowm.xchart:xchart, from Maven Central, declared in bench/charts/pom.xml);
# Maven fetches it on the first run.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
results="${1:-$here/results}"
images="${2:-$root/docs/images}"
command -v mvn >/dev/null 2>&1 || { echo "charts: Maven (mvn) is needed; install it (Debian: apt-get install maven)" >&2; exit 3; }
cp_file="$(mktemp)"
trap 'rm -f "$cp_file"' EXIT
if ! mvn -B -q -f "$here/charts/pom.xml" dependency:build-classpath -Dmdep.outputFile="$cp_file" >"$cp_file.log" 2>&1; then
  cat "$cp_file.log" >&2; rm -f "$cp_file.log"
  echo "charts: could not resolve XChart with Maven" >&2
  exit 3
fi
rm -f "$cp_file.log"
java -Djava.awt.headless=true -cp "$(cat "$cp_file")" "$here/charts/BenchCharts.java" "$results" "$images"
