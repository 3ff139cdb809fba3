# Shared by the whole-process timing scripts in bench/ (sourced, not run).

# The median of the numbers on stdin, one per line.
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# Sets `runs` from a leading `-n RUNS` (else DEFAULT) and `rest` to the
# arguments after it:  parse_runs DEFAULT "$@"; set -- "${rest[@]}"
parse_runs() {
  runs=$1
  shift
  if [[ "${1:-}" == "-n" ]]; then
    runs=$2
    shift 2
  fi
  rest=("$@")
}
