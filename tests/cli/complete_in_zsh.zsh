# zsh -f complete_in_zsh.zsh MODE FILE OUT LINE...: starts an interactive zsh on a pseudo-terminal
# (zpty), loads the completion FILE the way MODE says (fpath: FILE's directory in $fpath, as
# `cmake --install` puts _vbim in share/zsh/site-functions; source: `source FILE` after compinit),
# types each LINE and a Tab, and appends the line as the completion left it, [BUFFER], to OUT.
# Exits 1 if a line is not done within 30 s. Used by tests/cli/habits_test.cpp.
mode=$1 file=$2 out=$3
shift 3
zmodload zsh/zpty || exit 1
zpty z zsh -f -i
if [[ $mode == fpath ]]; then
  zpty -w z "PS1='> '; fpath=(${file:h} \$fpath); autoload -U compinit; compinit -u -D; unsetopt beep"
else
  zpty -w z "PS1='> '; autoload -U compinit; compinit -u -D; source $file; unsetopt beep"
fi
# Ctrl-X writes the line and clears it for the next; the shell's PID, to end it.
zpty -w z "print \$\$ >$out.pid"
zpty -w z 'show() { print -r -- "[$BUFFER]" >>'"$out"'; BUFFER=; }; zle -N show; bindkey "^X" show'
result=0 done=0
for line in "$@"; do
  zpty -w -n z "$line"$'\t\x18'
  (( done++ ))
  # Wait for this line, reading the terminal meanwhile so that the shell never blocks writing to it.
  for i in {1..300}; do
    [[ -f $out ]] && (( $(wc -l <$out) >= done )) && break
    zpty -r -t z junk 2>/dev/null
    sleep 0.1
  done
  (( $(wc -l <$out 2>/dev/null || echo 0) >= done )) || { print -u2 "no completion of '$line' in 30 s"; result=1; break; }
done
# The shell under the pseudo-terminal ignores the hang-up zpty -d sends: end it first.
[[ -f $out.pid ]] && kill -KILL $(<$out.pid) 2>/dev/null
rm -f $out.pid
zpty -d z
exit $result
