#!/usr/bin/env bash
# The manual page grainlab.1, made from the executable's own --help texts so that it cannot
# drift from them (the build runs this after linking grainlab):
#   make_man_page.sh GRAINLAB_EXECUTABLE OUTPUT_FILE
# Every subcommand's help, found by walking the "Subcommands:" lists, becomes a section.
set -euo pipefail
exe="$1" out="$2"

# The resources' folder as this executable finds it (PREFIX/share/grainlab), which defaults in
# the help texts name: the page names the installed one.
resources="$(realpath -s -m "$(dirname "$exe")/../share/grainlab")"

# One --help text, with the executable's path in its usage line replaced by its name.
help_of() {
  QT_QPA_PLATFORM=offscreen "$exe" "$@" --help |
    sed -E -e "s#^Usage: [^ ]*grainlab#Usage: grainlab#" -e "s#${resources}#/usr/share/grainlab#g"
}

# The subcommands a help text lists.
subcommands_of() {
  help_of "$@" | awk '/^Subcommands:/ {on = 1; next} on && /^  [a-z]/ {print $1} on && /^$/ {on = 0}'
}

# Text as roff: backslashes and minus signs escaped, a line starting with . or ' protected.
roff() {
  sed -e 's/\\/\\e/g' -e 's/-/\\-/g' -e "s/^\\([.']\\)/\\\\\&\\1/"
}

# A help text as a section: its first line (what the command does) as a paragraph, the rest as
# it is printed.
section() {
  local text
  text="$(help_of "$@")"
  if [[ $# -gt 0 ]]; then
    echo ".SS \"grainlab $*\""
    printf '%s\n' "$text" | head -n 1 | roff
  fi
  echo ".PP"
  echo ".nf"
  printf '%s\n' "$text" | tail -n +2 | sed '/^$/N;/^\n$/D' | roff
  echo ".fi"
}

walk() {
  local sub
  for sub in $(subcommands_of "$@"); do
    section "$@" "$sub"
    walk "$@" "$sub"
  done
}

version="$(QT_QPA_PLATFORM=offscreen "$exe" --version | head -n 1)"
summary="$(help_of | head -n 1 | sed 's/^GrainLab: //')"
{
  echo ".TH GRAINLAB 1 \"\" \"GrainLab ${version}\" \"User Commands\""
  echo ".SH NAME"
  echo "grainlab \\- $(printf '%s' "$summary" | roff)"
  echo ".SH SYNOPSIS"
  echo ".B grainlab"
  echo "[\\fIOPTIONS\\fR] [\\fISUBCOMMAND\\fR] ..."
  echo ".SH DESCRIPTION"
  echo "Without a subcommand, grainlab opens its window with the quick experiment (or the one"
  echo "given with \\-\\-experiment). The subcommands run headless: no display is needed."
  echo "This page is made from the program's own \\-\\-help texts; the user guide and the"
  echo "formats of every file are in /usr/share/doc/grainlab."
  section
  echo ".SH SUBCOMMANDS"
  walk
  echo ".SH VERSION"
  printf '%s\n' "$version" | roff
} > "$out"
