#!/usr/bin/env bash
# Runs `vissort order FILE --size 128x128` on every file under a folder of models (by default
# Debian's assimp-testmodels, /usr/share/assimp/models) and prints one line per file:
#   exit code, wall seconds, peak memory (MB), file, the last line of stderr.
# A crash shows as an exit code >= 128, a hang as 124 (timeout), memory out of proportion as a
# large peak. Each run is capped by `timeout` and an address-space limit, so a hostile file
# cannot take the machine down.
#   bash scripts/sweep-models.sh [FOLDER] [TOOL]      (TOOL: build/vissort)
# Environment: SWEEP_TIMEOUT (20 s), SWEEP_MEMORY_MB (4096).
set -uo pipefail
folder=${1:-/usr/share/assimp/models}
tool=${2:-build/vissort}
limit_s=${SWEEP_TIMEOUT:-20}
limit_mb=${SWEEP_MEMORY_MB:-4096}
[ -x "$tool" ] || { echo "sweep-models: no tool at $tool (build vissort_cli first)" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "sweep-models: /usr/bin/time is missing (apt-get install time)" >&2; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
printf 'code\tseconds\tpeak_mb\tfile\tmessage\n'
find "$folder" -type f | LC_ALL=C sort | while IFS= read -r file; do
  ( ulimit -v $((limit_mb * 1024))
    /usr/bin/time -v -o "$scratch/time" timeout "$limit_s" "$tool" order "$file" --size 128x128 \
      >/dev/null 2>"$scratch/err" )
  code=$?
  # time -v reports the command's status too; the exit code of time itself is the tool's.
  seconds=$(awk -F': ' '/Elapsed \(wall clock\)/ {n=split($2,a,":"); s=0; for(i=1;i<=n;i++) s=s*60+a[i]; print s}' "$scratch/time")
  peak=$(awk -F': ' '/Maximum resident set size/ {printf "%d", $2/1024}' "$scratch/time")
  message=$(tail -n 1 "$scratch/err" | tr '\t' ' ' | cut -c1-200)
  printf '%s\t%s\t%s\t%s\t%s\n' "$code" "$seconds" "$peak" "$file" "$message"
done
