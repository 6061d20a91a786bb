#!/usr/bin/env bash
# Inputs that are not files, or absurd (issue 33 section 3, docs/robustness.md "Input files"): each
# is refused by name before any work, never a hang or a file read without end.
# Usage: input_files.sh path/to/rtusim
set -euo pipefail
rtusim=$1
source "$(dirname "${BASH_SOURCE[0]}")/shell_test_helpers.sh"

"$rtusim" build --scene sphere --depth 4 --out sphere.svo >/dev/null
"$rtusim" jobs --width 8 --height 8 --out jobs.bin >/dev/null
mkfifo fifo
mkdir folder

# Special files: a FIFO would block the open forever (timeout turns a hang into a failure), a
# device never ends, a directory used to be "9223372036854775807 bytes".
in_time() { timeout 20 "$@"; }
expect_error "SVO image 'folder' is not a regular file (a directory)" \
  in_time "$rtusim" render --svo folder --width 8 --height 8
expect_error "SVO image 'fifo' is not a regular file (a FIFO)" \
  in_time "$rtusim" golden --svo fifo --jobs jobs.bin --out out.bin
expect_error "job buffer 'fifo' is not a regular file (a FIFO)" \
  in_time "$rtusim" golden --svo sphere.svo --jobs fifo --out out.bin
expect_error "mesh file '/dev/zero' is not a regular file (a character device)" \
  in_time "$rtusim" build --mesh /dev/zero --out m.svo
expect_error "binvox file 'fifo' is not a regular file (a FIFO)" \
  in_time "$rtusim" build --binvox fifo --out m.svo
expect_error "'fifo' is not a regular file (a FIFO)" in_time "$rtusim" config --dump --config fifo
expect_error "'fifo' is not a regular file (a FIFO)" \
  in_time "$rtusim" sweep --sweep-file fifo --out sweep --dry-run
expect_error "'fifo' is not a regular file (a FIFO)" in_time "$rtusim" validate fifo
expect_error "--scene-file: 'fifo' is not a regular file (a FIFO)" \
  in_time "$rtusim" animate --scene-file fifo
for model in /dev/zero /dev/urandom; do
  printf '[models.ball]\nmesh = "%s"\n[[instances]]\nmodel = "ball"\n' "$model" >scene.toml
  expect_error "key 'models.ball.mesh': '$model' is not a regular file (a character device)" \
    in_time "$rtusim" animate --scene-file scene.toml --frames 1 --width 8 --height 6
done
printf '[models.ball]\nbinvox = "fifo"\n[[instances]]\nmodel = "ball"\n' >scene.toml
expect_error "key 'models.ball.binvox': 'fifo' is not a regular file (a FIFO)" \
  in_time "$rtusim" animate --scene-file scene.toml --frames 1 --width 8 --height 6

# Nesting: 20,000 levels of JSON and 100,000 parts of a TOML key overflowed the stack (SIGSEGV).
python3 -c "print('{\"a\": ' + '[' * 20000 + ']' * 20000 + '}')" >deep.json
expect_error "'deep.json': nested more than 64 levels deep at line 1" \
  "$rtusim" config --dump --config deep.json
python3 -c "print('x = 1\n' + '.'.join(['a'] * 100000) + ' = 1')" >deep.toml
expect_error "'deep.toml': nested more than 64 levels deep at line 2" \
  "$rtusim" config --dump --config deep.toml
expect_error "sweep file 'deep.toml': nested more than 64 levels deep at line 2" \
  "$rtusim" sweep --sweep-file deep.toml --out sweep --dry-run
expect_error "scene file 'deep.toml': nested more than 64 levels deep at line 2" \
  "$rtusim" animate --scene-file deep.toml --frames 1

# Cameras that make no rays: an up vector of zero rendered an empty frame with exit 0.
expect_error "camera.up must be a non-zero vector, got 0,0,0" \
  "$rtusim" render --scene sphere --depth 3 --width 8 --height 8 --up 0,0,0
expect_error "camera.up (1,1,1) is parallel to the view direction" \
  "$rtusim" render --scene sphere --depth 3 --width 8 --height 8 --camera -2,-2,-2 --look-at 0,0,0 \
  --up 1,1,1
expect_error "camera.up must be a non-zero vector" \
  "$rtusim" jobs --width 8 --height 8 --up 0,0,0 --out j.bin
printf '[models.ball]\nprocedural = "sphere"\ndepth = 3\n[[instances]]\nmodel = "ball"\n[camera]\nup = [0, 0, 0]\nkeys = [{ time = 0.0, position = [0, 1, -3], look_at = [0, 0, 0] }]\n' >scene.toml
expect_error "camera.up must be a non-zero vector" \
  "$rtusim" animate --scene-file scene.toml --frames 1 --width 8 --height 6

# One stack rule for every command (docs/robustness.md): a tree deeper than --stack-frames is
# refused naming its file or scene, or traced with its overflowing rays flagged given
# --allow-stack-overflow. accuracy ignored the depth (overflowing rays as "50 % agreement") and
# golden and render --model golden only warned.
"$rtusim" build --scene sphere --depth 6 --out deep.svo >/dev/null
deeper="needs 5 stack frames; 3 are configured"
expect_error "SVO image 'deep.svo': the tree at root 0 has descriptors at depth 5 and $deeper" \
  "$rtusim" golden --svo deep.svo --jobs jobs.bin --out out.bin --stack-frames 3
expect_error "SVO image 'deep.svo': the tree at root 0 has descriptors at depth 5 and $deeper" \
  "$rtusim" accuracy --svo deep.svo --stack-frames 3 --width 8 --height 8
expect_error "SVO image 'deep.svo': the tree at root 0 has descriptors at depth 5 and $deeper" \
  "$rtusim" render --model golden --svo deep.svo --stack-frames 3 --width 8 --height 8
expect_error "--depth 6 builds descriptors down to level 5, which $deeper" \
  "$rtusim" accuracy --scene sphere --depth 6 --stack-frames 3 --width 8 --height 8
"$rtusim" golden --svo deep.svo --jobs jobs.bin --out out.bin --stack-frames 3 \
  --allow-stack-overflow >/dev/null 2>err.txt
grep -q "deeper rays will be flagged" err.txt || fail "golden --allow-stack-overflow did not warn"
echo "input files: all checks passed"
