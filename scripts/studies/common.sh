# What the studies of scripts/studies/ share; each study sources it first:
#   source "$(dirname "$0")/common.sh"
# and it sets
#   study      the study's name (its file name), for messages
#   root       the repository's root
#   exe        the program: $RING_CONTACT if set, else build/ring_contact
#              (a study that takes the program as an argument sets it again)
#   figures    doc/figures/
#   plot_only  true when the study was called with --plot-only (the
#              argument is removed from "$@"): redraw the figures from the
#              committed data in doc/data/ alone, without running anything
#   work       a temporary folder, removed when the study ends
# and gives the functions below (rc_...). A run's success is read from its
# exit code and its files (history.csv, verdicts.csv), never from what the
# program prints: that text is for people and may change.
#
# Exit codes of ring_contact: 0 every check passed; 1 a check failed (the
# results are complete and valid); 2 the input was refused; 3 a load step
# could not be solved (history.csv holds the converged steps); 130 / 143
# interrupted. Programs built before these codes said 1 for 1, 2 and 3:
# for exit code 1 the files tell which (rc_status).

study=$(basename "$0")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
exe=${RING_CONTACT:-$root/build/ring_contact}
figures=$root/doc/figures
plot_only=false
if [ "${1:-}" = "--plot-only" ]; then
  plot_only=true
  shift
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/ring_contact_$study.XXXXXX")
trap 'rm -rf "$work"' EXIT

rc_say() { # message...: a line on stderr, with the study's name
  printf '%s: %s\n' "$study" "$*" >&2
}

# rc_prm NAME BASE [OVERRIDES]: write $work/NAME.prm, which includes BASE (a
# shipped .prm, relative to the root or absolute; none if empty), asks for
# a quiet run (no Newton lines, no step lines, no timing table, no VTU
# files) with its results in $work/NAME/, then the OVERRIDES (.prm text:
# 'subsection ... set ... end'; an entry set again there wins, e.g.
# Output/VTU interval).
rc_prm() {
  local name=$1 base=$2 overrides=${3:-}
  case $base in
    "") ;;
    /*) ;;
    *) base=$root/$base ;;
  esac
  {
    [ -z "$base" ] || echo "include $base"
    cat <<PRM
subsection Newton
  set Verbose = false
end
subsection Output
  set Directory    = $work/$name
  set VTU interval = 0
  set Print steps  = false
  set Print timing = false
end
PRM
    [ -z "$overrides" ] || printf '%s\n' "$overrides"
  } > "$work/$name.prm"
}

# rc_status CODE FOLDER: the outcome of a run from its exit code and, for
# exit code 1, its files: pass, fail (a check failed; results complete),
# refused (nothing written), unsolved (a step could not be solved: the
# history stops short), interrupted, or error (any other end).
rc_status() {
  local code=$1 folder=$2
  case $code in
    0) echo pass ;;
    2) echo refused ;;
    3) echo unsolved ;;
    130|143) echo interrupted ;;
    1)
      # Today's exit code 1 also means 2 or 3. Nothing written: the input
      # or the mesh was refused before the first step (an earlier run's
      # files are removed only then, and the folder is new).
      if [ ! -f "$folder/history.csv" ]; then
        echo refused
      elif rc_stopped_short "$folder"; then
        echo unsolved
      elif [ -f "$folder/verdicts.csv" ] &&
           awk -F, 'NR > 1 && $NF == "FAIL" { found = 1 } END { exit !found }' \
             "$folder/verdicts.csv"; then
        echo fail
      else
        echo error
      fi ;;
    *) echo error ;;
  esac
}

# rc_stopped_short FOLDER: true if the run's history stops before the end
# of its load program: no converged step, a check of a 'step not reached'
# in verdicts.csv, or schemes whose last steps differ. (A run without
# checks whose every scheme stopped at the same step is not seen: the
# files do not say how many steps there were; exit code 3 does.)
rc_stopped_short() {
  local folder=$1
  [ "$(wc -l < "$folder/history.csv")" -ge 2 ] || return 0
  if [ -f "$folder/verdicts.csv" ] &&
     grep -q ',step not reached,' "$folder/verdicts.csv"; then
    return 0
  fi
  awk -F, 'NR > 1 { last[$1] = $2 + 0 }
    END { for (s in last) { if (n++ && last[s] != first) exit 0; first = last[s] }
          exit 1 }' "$folder/history.csv"
}

# rc_run NAME: run the program on $work/NAME.prm in $work (its output in
# $work/NAME.log, its errors in $work/NAME.err, its results in $work/NAME/),
# print a progress line on stderr and set
#   rc_code     the exit code
#   rc_outcome  pass, fail, refused, unsolved, interrupted or error
#   rc_history  $work/NAME/history.csv
#   rc_text     the outcome in words
# Returns 0 when the results are complete (pass or fail: every step of
# every scheme converged), 1 otherwise (with the end of the program's
# messages on stderr). An interrupted run ends the study with its code.
rc_run() {
  local name=$1 start=$EPOCHREALTIME
  # The run starts in $work: a program given by a relative path or by its
  # name in PATH is made absolute first.
  case $exe in
    /*) ;;
    */*) exe=$PWD/$exe ;;
    *) exe=$(command -v "$exe" || echo "$exe") ;;
  esac
  if [ ! -x "$exe" ]; then
    rc_say "no program at $exe: build it first (bash scripts/build)"
    exit 1
  fi
  rc_code=0
  (cd "$work" && "$exe" "$name.prm" > "$name.log" 2> "$name.err") || rc_code=$?
  rc_outcome=$(rc_status "$rc_code" "$work/$name")
  rc_history=$work/$name/history.csv
  local seconds steps=0
  seconds=$(awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }')
  [ ! -f "$rc_history" ] || steps=$(($(wc -l < "$rc_history") - 1))
  case $rc_outcome in
    pass)        rc_text="done" ;;
    fail)        rc_text="done, a check failed" ;;
    refused)     rc_text="input refused" ;;
    unsolved)    rc_text="stopped early: a step could not be solved" ;;
    interrupted) rc_text="interrupted" ;;
    *)           rc_text="ended with an error" ;;
  esac
  rc_say "$name: $rc_text (exit code $rc_code, $steps rows in history.csv, $seconds s)"
  case $rc_outcome in
    pass|fail) return 0 ;;
    interrupted) exit "$rc_code" ;;
  esac
  rc_log_tail "$name"
  return 1
}

# rc_log_tail NAME [LINES]: the end of a run's messages, on stderr.
rc_log_tail() {
  local name=$1 lines=${2:-3}
  if [ -s "$work/$name.err" ]; then
    tail -n "$lines" "$work/$name.err" | sed 's/^/    /' >&2
  else
    tail -n "$lines" "$work/$name.log" | sed 's/^/    /' >&2
  fi
}

# rc_reason NAME: why the last run (NAME) was refused or stopped, on one
# line for a table: the program's last message on stderr, or else what its
# exit code and files say (rc_text).
rc_reason() {
  local name=$1 line=""
  [ ! -s "$work/$name.err" ] ||
    line=$(grep -v '^[[:space:]]*$' "$work/$name.err" | tail -n 1 | cut -c1-160)
  echo "${line:-$rc_text}"
}

# rc_unknowns NAME: the number of unknowns of the run, the one figure read
# from the program's text (no file holds it): the first 'N unknowns' of its
# log; empty, with a warning, if the log does not say it.
rc_unknowns() {
  local name=$1 n
  n=$(grep -o -m1 -E '[0-9]+ unknowns' "$work/$name.log" | grep -o -E '^[0-9]+' || true)
  [ -n "$n" ] || rc_say "$name: the log does not give the number of unknowns"
  echo "$n"
}

# ---- Figures (gnuplot) -------------------------------------------------

# rc_gnuplot: run gnuplot on its standard input.
rc_gnuplot() {
  if ! command -v gnuplot > /dev/null; then
    rc_say "gnuplot is missing (bash scripts/install-dependencies gnuplot-nox)"
    return 1
  fi
  gnuplot
}

# rc_gp_begin FILE WIDTH HEIGHT: the terminal (PNG, enhanced text), the
# output doc/figures/FILE, the line styles 1 to 9 (rc_gp_styles), and the
# small grey note at the bottom right saying how to redraw it (label 99,
# under the x label: bottom margin 4.5 characters; a multiplot unsets it
# after its first panel).
rc_gp_begin() {
  local file=$1 width=$2 height=$3
  echo "set terminal pngcairo enhanced size $width,$height font ',11'"
  echo "set output '$figures/$file'"
  echo "set encoding utf8"
  echo "set datafile separator ','"
  echo "set grid lc rgb '#dddddd'"
  echo "set bmargin 4.5"
  echo "set label 99 'regenerate: bash scripts/studies/$study [--plot-only]' at screen 0.995, screen 0.01 right font ',8' textcolor rgb '#777777' noenhanced"
  rc_gp_styles
}

# rc_gp_styles: nine line styles that differ in colour (Okabe and Ito's
# palette, black and two more), dash type and marker, so that curves stay
# apart in grey too.
rc_gp_styles() {
  cat <<'GP'
set style line 1 lc rgb '#0072B2' lw 2 dt 1 pt 7 ps 1.1
set style line 2 lc rgb '#D55E00' lw 2 dt 2 pt 5 ps 1.0
set style line 3 lc rgb '#009E73' lw 2 dt 4 pt 9 ps 1.2
set style line 4 lc rgb '#CC79A7' lw 2 dt 5 pt 13 ps 1.2
set style line 5 lc rgb '#E69F00' lw 2 dt 3 pt 6 ps 1.3
set style line 6 lc rgb '#56B4E9' lw 2 dt (12,5,2,5) pt 4 ps 1.2
set style line 7 lc rgb '#000000' lw 2 dt 1 pt 8 ps 1.3
set style line 8 lc rgb '#999933' lw 2 dt 2 pt 12 ps 1.3
set style line 9 lc rgb '#882255' lw 2 dt 4 pt 2 ps 1.2
GP
}

# rc_gp_plot CURVE...: a plot command of curves, each CURVE
# 'DATA|STYLE|TITLE[|EVERY[|OFFSET[|LINE]]]': the 'x,y' lines of file DATA
# in line style STYLE, with a marker on every EVERY-th point (default: about
# eight along the curve) from point OFFSET on (default: one that depends on
# STYLE, so that the markers of coincident curves fall between each other),
# and TITLE in the key; LINE adds to the line's style, not to the key's
# sample (e.g. 'lw 4': a wide line under a coincident one). Every line is drawn first, in the order
# given, then every marker, then the key entries: no line hides a marker.
rc_gp_plot() {
  local spec data style title every offset line n lines="" points="" keys=""
  for spec in "$@"; do
    IFS='|' read -r data style title every offset line <<< "$spec"
    if [ -z "$every" ]; then
      n=$(grep -c . "$data" || true)
      every=$((n / 8))
      [ "$every" -ge 1 ] || every=1
    fi
    [ -n "$offset" ] || offset=$(( (style - 1) * every / 9 % every ))
    lines+="${lines:+, }'$data' using 1:2 with lines ls $style $line notitle"
    points+=", '$data' using 1:2 every $every::$offset with points ls $style lw 1.5 notitle"
    keys+=", NaN with linespoints ls $style title '$title'"
  done
  echo "plot $lines$points$keys"
}

# rc_curve CSV KEYCOL KEY XCOL YEXPR > DATA: the rows of CSV (header
# skipped) whose column KEYCOL is KEY, as 'x,y' lines: x is column XCOL,
# y the awk expression YEXPR of the row's fields ($1, $2, ...).
rc_curve() {
  local csv=$1 keycol=$2 key=$3 xcol=$4 yexpr=$5
  awk -F, -v k="$keycol" -v key="$key" -v x="$xcol" \
    "NR > 1 && \$k == key { printf \"%s,%.12g\\n\", \$x, $yexpr }" "$csv"
}
