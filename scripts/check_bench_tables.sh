#!/bin/sh
# Checks that every benchmark table says how to reproduce its figures and when they were measured
# (the convention of bench/README.md, "How a table is written"). Reads bench/README.md and
# bench/*/README.md (or the files given), builds nothing, and takes well under a second.
#
# A table is a run of lines that start with "|", its second line the separator (|---|...). A body
# row carries a figure when it holds a digit. A table with such rows passes when either
#   (a) it has a column headed "command" and one headed "measured": in every row with a figure the
#       command cell holds a command in backticks and the measured cell a date (YYYY-MM-DD) and a
#       commit (7 to 40 hex digits); or
#   (b) the text above it (back to the previous heading or table, at most 15 lines) has a line that
#       starts with "Command:" or "Commands:" followed by a command in backticks, and says
#       "Measured" with a date (YYYY-MM-DD) and a commit. A column headed "measured" may give the
#       date and commit row by row instead (then each row with a figure must have them).
# Prints FILE:LINE: WHAT for each table (or row) that fails, and exits 1 if any did, 2 if a file is
# missing, 0 otherwise.
# Usage: scripts/check_bench_tables.sh [FILE...]
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "$#" -eq 0 ]; then
  cd "$root" || exit 2
  set -- bench/README.md bench/*/README.md
fi
for f in "$@"; do
  [ -f "$f" ] || { echo "$f: no such file" >&2; exit 2; }
done

awk '
function trim(s) { sub(/^[ \t]+/, "", s); sub(/[ \t]+$/, "", s); return s }
# Whether s holds a date YYYY-MM-DD.
function hasDate(s) { return s ~ /(^|[^0-9])20[0-9][0-9]-[01][0-9]-[0-3][0-9]([^0-9]|$)/ }
# Whether s holds a commit: a word of 7 to 40 lowercase hex digits, at least one of them 0-9 (so
# that a word such as "defaced" is none; an abbreviated hash may be digits alone: 9629272).
function hasCommit(s,    n, i, w, words) {
  n = split(s, words, /[^0-9A-Za-z]+/)
  for (i = 1; i <= n; i++) {
    w = words[i]
    if (length(w) >= 7 && length(w) <= 40 && w !~ /[^0-9a-f]/ && w ~ /[0-9]/) return 1
  }
  return 0
}
function hasCommand(s) { return s ~ /`[^`]+`/ }
# The cells of a table line, in cell[1..n]; returns n.
function cells(line, cell,    n, i, parts) {
  line = trim(line); sub(/^\|/, "", line); sub(/\|$/, "", line)
  gsub(/\\\|/, "\001", line)  # an escaped pipe inside a cell
  n = split(line, parts, /\|/)
  for (i = 1; i <= n; i++) cell[i] = trim(parts[i])
  return n
}
function fail(file, line, what) { printf "%s:%d: %s\n", file, line, what; bad = 1 }
function checkFile(file, nl, text,    i, j, k, n, c, cmdCol, measCol, figures, pre, hasCmdLine, hdr, row, firstFig) {
  inFence = 0
  for (i = 1; i <= nl; i++) {
    if (text[i] ~ /^[ \t]*```/) { inFence = !inFence; continue }
    if (inFence) continue
    if (text[i] !~ /^[ \t]*\|/ || i == nl || text[i + 1] !~ /^[ \t]*\|[ \t]*:?-+/) continue
    # A table: header i, separator i+1, body to j.
    for (j = i + 2; j <= nl && text[j] ~ /^[ \t]*\|/; j++) ;
    j--
    n = cells(text[i], hdr)
    cmdCol = 0; measCol = 0
    for (c = 1; c <= n; c++) {
      if (tolower(hdr[c]) ~ /command/) cmdCol = c
      if (tolower(hdr[c]) ~ /measured/) measCol = c
    }
    figures = 0; firstFig = 0
    for (k = i + 2; k <= j; k++) if (text[k] ~ /[0-9]/) { figures++; if (!firstFig) firstFig = k }
    if (figures == 0) { i = j; continue }
    # The text above the table, back to the previous heading or table (at most 15 lines).
    pre = ""; hasCmdLine = 0
    for (k = i - 1; k >= 1 && k >= i - 15; k--) {
      if (text[k] ~ /^[ \t]*\|/ || text[k] ~ /^#/) break
      pre = text[k] " " pre
    }
    # A "Command:" line: the command in backticks on it or on the two lines after it.
    for (k = i - 1; k >= 1 && k >= i - 15; k--) {
      if (text[k] ~ /^[ \t]*\|/ || text[k] ~ /^#/) break
      if (text[k] ~ /^[ \t]*(- )?Commands?:/ && hasCommand(text[k] " " (k + 1 < i ? text[k + 1] : "") " " (k + 2 < i ? text[k + 2] : ""))) hasCmdLine = 1
    }
    for (k = i + 2; k <= j; k++) {
      if (text[k] !~ /[0-9]/) continue
      cells(text[k], row)
      if (cmdCol && !hasCommand(row[cmdCol]))
        fail(file, k, "row with a figure: no command in backticks in its \"" hdr[cmdCol] "\" cell")
      if (measCol && !(hasDate(row[measCol]) && hasCommit(row[measCol])))
        fail(file, k, "row with a figure: no date (YYYY-MM-DD) and commit in its \"" hdr[measCol] "\" cell")
    }
    if (!cmdCol && !hasCmdLine)
      fail(file, firstFig, "table with figures in " figures " row(s) has no \"Command:\" line with a `command` in the 15 lines above it (since the last heading or table), nor a \"command\" column")
    if (!measCol && !(pre ~ /[Mm]easured/ && hasDate(pre) && hasCommit(pre)))
      fail(file, firstFig, "table with figures in " figures " row(s) has no \"Measured\" date (YYYY-MM-DD) and commit in the 15 lines above it (since the last heading or table), nor a \"measured\" column")
    i = j
  }
}
FNR == 1 && NR > 1 { checkFile(file, nl, text); delete text }
{ file = FILENAME; nl = FNR; text[FNR] = $0 }
END { if (NR > 0) checkFile(file, nl, text); exit bad }
' "$@"
status=$?
[ "$status" -eq 0 ] && echo "check_bench_tables: every benchmark table names its command, date and commit ($# files)"
exit "$status"
