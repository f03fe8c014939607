#!/bin/bash
# Bad inputs of issue 2 §3: each must exit with the right code, print one short line on
# stderr naming the problem, and leave no output file behind.
# usage: bad_input_test.sh CLI SHARED_MODELS_DIR
cli=$1; models=$2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
good=$models/component8.step
shell=$models/cube_filet.stp   # a model without solids
: > "$t/empty.step"
head -c 20000 /dev/urandom > "$t/garbage.step"
echo "hello world" > "$t/text.stp"
head -c $(( $(stat -c %s "$good") / 3 )) "$good" > "$t/truncated.step"
printf '\x89PNG\r\n\x1a\n' > "$t/image.igs"; head -c 5000 /dev/urandom >> "$t/image.igs"
echo "garbage" > "$t/shape.brep"
cp "$good" "$t/model.xyz"
mkdir "$t/dir.step"
printf 'ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n' > "$t/nodata.step"
touch "$t/noread.step"; chmod 000 "$t/noread.step"
pass=0; fail=0
check() { # name expected-exit must-mention args...
  local name=$1 want=$2 word=$3; shift 3
  rm -f "$t/out.msh" "$t/rep.json"
  timeout 120 "$cli" "$@" > "$t/so" 2> "$t/se"; local rc=$?
  local why=""
  [ $rc -eq $want ] || why="exit $rc (want $want)"
  [ -z "$why" ] && ! [ -s "$t/se" ] && why="no message on stderr"
  [ -z "$why" ] && [ "$(wc -l < "$t/se")" -ne 1 ] && why="message is not one line: $(head -c 300 "$t/se")"
  [ -z "$why" ] && ! grep -qi -- "$word" "$t/se" && why="message does not mention '$word': $(cat "$t/se")"
  [ -z "$why" ] && [ -e "$t/out.msh" ] && why="left an output file"
  [ -z "$why" ] && ls "$t" | grep -q '\.tmp' && why="left a temporary file"
  if [ -z "$why" ]; then pass=$((pass+1)); echo "ok $name: $(cat "$t/se")"; else fail=$((fail+1)); echo "FAIL $name: $why"; fi
}
check missing 2 nonexistent.step mesh "$t/nonexistent.step" -o "$t/out.msh"
check empty 2 empty mesh "$t/empty.step" -o "$t/out.msh"
check garbage 2 garbage.step mesh "$t/garbage.step" -o "$t/out.msh"
check text 2 text.stp mesh "$t/text.stp" -o "$t/out.msh"
check truncated 2 truncated mesh "$t/truncated.step" -o "$t/out.msh"
check png-as-iges 2 image.igs mesh "$t/image.igs" -o "$t/out.msh"
check bad-brep 2 shape.brep mesh "$t/shape.brep" -o "$t/out.msh"
check unknown-ext 2 extension mesh "$t/model.xyz" -o "$t/out.msh"
check directory 2 directory mesh "$t/dir.step" -o "$t/out.msh"
check no-data 2 nodata.step mesh "$t/nodata.step" -o "$t/out.msh"
if [ "$(id -u)" -ne 0 ]; then check unreadable 2 noread mesh "$t/noread.step" -o "$t/out.msh"; fi
check info-missing 2 nonexistent info "$t/nonexistent.step"
check info-garbage 2 garbage info "$t/garbage.step"
check negative-size 2 size mesh "$good" -o "$t/out.msh" --size -1
check zero-size 2 size mesh "$good" -o "$t/out.msh" --size 0
check negative-hmax 2 hmax mesh "$good" -o "$t/out.msh" --hmax -3
check hmin-over-hmax 2 hmin mesh "$good" -o "$t/out.msh" --hmax 1 --hmin 2
check bad-gradation 2 gradation mesh "$good" -o "$t/out.msh" --gradation 0.5
check bad-anisotropy 2 anisotropy mesh "$good" -o "$t/out.msh" --anisotropy 0
check not-a-number 2 size mesh "$good" -o "$t/out.msh" --size abc
check bad-dim 2 dim mesh "$good" -o "$t/out.msh" --dim 4
check bad-order 2 order mesh "$good" -o "$t/out.msh" --order 3
check bad-threads 2 threads mesh "$good" -o "$t/out.msh" --threads -2
check bad-format 2 format mesh "$good" -o "$t/out.unknownformat"
# a word outside an option's list is named with the words allowed, not CLI11's table
check bad-overlaps 2 "'foo' is not one of: merge, keep, error" mesh "$good" -o "$t/out.msh" --overlaps foo
check bad-quad-method 2 "not one of: merge, morph, mixed" mesh "$good" -o "$t/out.msh" --quad --quad-method x
check bad-msh-version 2 "'3' is not one of: 4.1, 2.2" mesh "$good" -o "$t/out.msh" --msh-version 3
check bad-internal-faces 2 "not one of: auto, crack, bond" mesh "$good" -o "$t/out.msh" --internal-faces y
check no-output 2 output mesh "$good"
check no-folder 2 folder mesh "$good" -o "$t/nofolder/out.msh"
check missing-sizing 2 sizing mesh "$good" -o "$t/out.msh" --sizing "$t/nosuch.json"
echo '{"sources": [{"type": "cone", "h": 1}]}' > "$t/badsizing.json"
check bad-sizing-source 2 'sources\[0\].type' mesh "$good" -o "$t/out.msh" --sizing "$t/badsizing.json"
echo '{"global": {"h": -1}}' > "$t/negsizing.json"
check negative-sizing 2 'global.h' mesh "$good" -o "$t/out.msh" --sizing "$t/negsizing.json"
check dim3-on-shell 2 solids mesh "$shell" -o "$t/out.msh" --dim 3
check unknown-option 2 no-such-option mesh "$good" -o "$t/out.msh" --no-such-option
check unknown-command 2 frobnicate frobnicate "$good"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
