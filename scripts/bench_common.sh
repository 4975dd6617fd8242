# Shared by the bench scripts (source it): time_runs and the machine line.

# label, command...: best and median wall seconds over ${n:-$runs} runs; FAILED if one fails.
time_runs() {
  local label=$1; shift
  local times=()
  for ((r = 0; r < ${n:-$runs}; ++r)); do
    local t0 t1
    t0=$(date +%s.%N)
    "$@" >/dev/null 2>&1 || { echo "$label: FAILED"; return 0; }
    t1=$(date +%s.%N)
    times+=("$(echo "$t1 - $t0" | bc)")
  done
  printf '%s\n' "${times[@]}" | sort -n | awk -v l="$label" '{a[NR]=$1} END {printf "%-64s best %7.2f s  median %7.2f s\n", l, a[1], a[int((NR+1)/2)]}'
}

# The machine, its load and the SIMD flags the numbers depend on.
print_machine() {
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "flags: $(grep -m1 flags /proc/cpuinfo | grep -o -w -E 'avx2|avx512f|fma' | sort -u | xargs)"
}
