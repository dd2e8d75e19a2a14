# shellcheck shell=bash
# What the shell scripts know of the repository's own programmes, in one place: sourced by
# bench/pgo-build, tests/pgo-same and tests/windows/run.

# The machine an example in examples/ is for, from its name; a name of no known machine fails.
machine_of() {
  case $(basename "$1") in
    fanuc0m_*) echo fanuc0m ;;
    fanuc0t_*) echo fanuc0t ;;
    gsk980tdi_*) echo gsk980tdi ;;
    gsk988t_*) echo gsk988t ;;
    yasnac_lx3_*) echo yasnac-lx3 ;;
    *) echo "no machine known for $1" >&2; return 1 ;;
  esac
}

# A golden case's command-line arguments into the array case_args (its args file, over one line
# or more; none without the file, as the golden tests read it) and its setup into case_setup.
read_case() {
  local dir=$1
  case_args=()
  if [[ -f $dir/args ]]; then read -rd '' -a case_args <"$dir/args" || true; fi
  case_setup=()
  if [[ -f $dir/setup.toml ]]; then case_setup=(--setup "$dir/setup.toml"); fi
}
