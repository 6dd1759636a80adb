#!/usr/bin/env bash
# Installing and packaging GrainLab, as a user would:
#   install_test.sh BUILD_DIR SOURCE_DIR
# cmake --install into a prefix, which is then moved (an installed GrainLab finds its resources
# from its own location, and no path of the source tree is compiled into it): the installed
# grainlab runs the tiny experiment from an unrelated folder, looks for its presets inside the
# prefix, and the installed Python module imports. Then cpack builds the Debian package: its
# name, its declared dependencies, its files (executable, presets, docs, desktop entry, icon,
# Python module), and the executable unpacked from it runs.
set -euo pipefail
build="$1" source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log" ||
  { cat "$work/install.log" >&2; fail "cmake --install"; }
mv "$work/prefix" "$work/moved"
prefix="$work/moved"
exe="$prefix/bin/grainlab"
[[ -x "$exe" ]] || fail "no $exe"
if grep -qF "$source_dir" "$exe"; then
  fail "the installed executable holds the source tree's path $source_dir"
fi
for f in share/man/man1/grainlab.1.gz share/doc/grainlab/copyright share/doc/grainlab/changelog.gz \
         share/grainlab/experiments/quick.json share/grainlab/studies/tiny.json \
         share/grainlab/stability/tiny.json share/doc/grainlab/python.md \
         share/applications/grainlab.desktop share/icons/hicolor/scalable/apps/grainlab.svg; do
  [[ -f "$prefix/$f" ]] || fail "not installed: $f"
done
mkdir "$work/elsewhere"
cd "$work/elsewhere"
# The version names the project's version and the commit built.
version="$(sed -n 's/^project(GrainLab VERSION \([0-9.]*\).*/\1/p' "$source_dir/CMakeLists.txt")"
"$exe" --version > version.txt || fail "grainlab --version"
grep -qE "^GrainLab $version \(commit ([0-9a-f]{12}(-modified)?|unknown)\)$" version.txt ||
  fail "grainlab --version printed: $(cat version.txt)"
"$exe" run --help > run-help.txt || fail "grainlab run --help"
grep -qF -- "--resume" run-help.txt || fail "grainlab run --help lacks --resume"
# The manual page is the --help texts: every subcommand, its options, no path of the build.
LC_ALL=C MANWIDTH=200 man -l "$prefix/share/man/man1/grainlab.1.gz" 2> man.err > man.txt || fail "man: $(cat man.err)"
for text in "grainlab run" "grainlab study collect" "grainlab stability cell" "--resume" \
            "--emit" "$(head -n 1 version.txt)"; do
  grep -qF -- "$text" man.txt || fail "the manual page lacks '$text'"
done
if grep -qF "$build" man.txt; then
  fail "the manual page names the build folder $build"
fi
env -u GRAINLAB_RESOURCES "$exe" run "$prefix/share/grainlab/experiments/tiny.json" --out run \
  --quiet > run.log 2>&1 || { cat run.log >&2; fail "the installed grainlab did not run tiny.json"; }
[[ -s run/p015kPa/series.csv ]] || fail "the installed grainlab wrote no series"
# A preset is looked for in the prefix it runs from.
if env -u GRAINLAB_RESOURCES "$exe" stability --preset no-such-preset --out map > preset.log 2>&1; then
  fail "an unknown preset was accepted"
fi
grep -qF "$prefix/bin/../share/grainlab/stability/no-such-preset.json" preset.log ||
  grep -qF "$prefix/share/grainlab/stability/no-such-preset.json" preset.log ||
  { cat preset.log >&2; fail "the preset was not looked for inside the prefix"; }
if [[ -d "$prefix/lib/python3/dist-packages/grainlab" ]]; then
  PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c "
import grainlab, sys
assert grainlab.__file__.startswith('$prefix'), grainlab.__file__
e = grainlab.Experiment.load('$prefix/share/grainlab/experiments/tiny.json')
assert grainlab.RunFolder('run').finished
" || fail "the installed Python module"
fi

# The Debian package.
command -v cpack > /dev/null || fail "no cpack"
cd "$build"
cpack -G DEB -B "$work/package" > "$work/cpack.log" 2>&1 || { cat "$work/cpack.log" >&2; fail "cpack"; }
deb="$work/package/grainlab_${version}_amd64.deb"
[[ -f "$deb" ]] || { ls "$work/package" >&2; fail "no package $deb"; }
depends="$(dpkg-deb -f "$deb" Depends)"
for lib in libqt6widgets6 libhdf5 libgomp1 libfmt9; do
  [[ "$depends" == *"$lib"* ]] || fail "Depends does not name $lib: $depends"
done
dpkg-deb -c "$deb" > "$work/contents"
for f in ./usr/bin/grainlab ./usr/share/grainlab/experiments/quick.json \
         ./usr/share/man/man1/grainlab.1.gz ./usr/share/doc/grainlab/copyright \
         ./usr/share/applications/grainlab.desktop \
         ./usr/share/icons/hicolor/scalable/apps/grainlab.svg ./usr/share/doc/grainlab/README.md; do
  grep -qF " $f" "$work/contents" || fail "the package lacks $f"
done
if [[ -d "$prefix/lib/python3/dist-packages/grainlab" ]]; then
  grep -qF " ./usr/lib/python3/dist-packages/grainlab/__init__.py" "$work/contents" ||
    fail "the package lacks the Python module"
fi
# Debian's own check of the package: no errors (warnings are printed).
if command -v lintian > /dev/null; then
  lintian --allow-root "$deb" > "$work/lintian.txt" 2>&1 || true
  cat "$work/lintian.txt"
  if grep -q "^E: " "$work/lintian.txt"; then
    fail "lintian reports errors"
  fi
fi
dpkg-deb -x "$deb" "$work/unpacked"
cd "$work/elsewhere"
"$work/unpacked/usr/bin/grainlab" run --resume run > resume.log 2>&1 ||
  { cat resume.log >&2; fail "the packaged grainlab does not run"; }
grep -q "finished" resume.log || fail "the packaged grainlab: $(cat resume.log)"
echo "ok: installed, moved, run; package $(basename "$deb") ($(du -h "$deb" | cut -f1)): $depends"
