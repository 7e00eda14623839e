#!/usr/bin/env bash
# Open show through the desktop's file dialog (docs/gui.md): a stand-in `zenity` on PATH (the
# protocol haze speaks: arguments in, the chosen path on stdout, exit 0 chosen, 1 cancelled)
# records its arguments. Ctrl+O with the dialog cancelled leaves the show open; Ctrl+O with a
# path opens that show (the title says so) and puts it in the recent list; the dialog was asked
# for a file, starting in the open show's folder, filtered to *.haze.json. With
# HAZE_FILE_DIALOG=typed the path popup is used instead (the walkthrough's Save as covers it).
set -uo pipefail
haze=$1; root=$2
. "$root/tests/gui/gui_session.bash"

mkdir -p "$tmp/show" "$tmp/bin"
cp "$root/tests/data/shows/console.haze.json" "$tmp/show/"
cp "$root/tests/data/shows/console.haze.json" "$tmp/show/other.haze.json"
cp -r "$root/tests/data/shows/profiles" "$tmp/show/"
cat > "$tmp/bin/zenity" <<'SH'
#!/bin/sh
printf '%s\n' "$@" > "$FAKE_DIALOG_ARGS"
[ -n "$FAKE_DIALOG_ANSWER" ] || exit 1
printf '%s\n' "$FAKE_DIALOG_ANSWER"
SH
chmod +x "$tmp/bin/zenity"
unset HAZE_FILE_DIALOG
export PATH="$tmp/bin:$PATH" FAKE_DIALOG_ARGS="$tmp/args.txt" FAKE_DIALOG_ANSWER=""
start_haze "haze - console" "$tmp/show/console.haze.json" --width 640 --height 360 --quality draft

tap ctrl+o
sleep 1
check "cancelling the dialog keeps the show (title '$(title)')" '[[ "$(title)" == "haze - console.haze.json" ]]'
check "the dialog was asked for a file" 'grep -qx -- "--file-selection" "$tmp/args.txt"'
check "starting in the show's folder" 'grep -qx -- "--filename=$tmp/show/" "$tmp/args.txt"'
check "showing shows" 'grep -qx -- "--file-filter=Shows | \*.haze.json" "$tmp/args.txt"'

# The answer is read when haze starts the dialog, so the next one is set in the environment of
# a second haze; this one quits.
tap ctrl+q
wait_exit
export FAKE_DIALOG_ANSWER="$tmp/show/other.haze.json"
start_haze "haze - console" "$tmp/show/console.haze.json" --width 640 --height 360 --quality draft
tap ctrl+o
sleep 1
check "the chosen show is open (title '$(title)')" '[[ "$(title)" == "haze - other.haze.json" ]]'
check "and in the recent files" 'grep -q "other.haze.json" "$XDG_CONFIG_HOME/haze/recent.txt"'
tap ctrl+q
wait_exit
check "Ctrl+Q exits cleanly (status $rc)" '[ "$rc" = 0 ]'
finish
