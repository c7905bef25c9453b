#!/usr/bin/env bash
# Checks that a refactor keeps every image's bits. `record DIR` renders every scene of scenes/ and
# bench/scenes/ (RGB and spectral, a few spp, small) with the current build, in one process, under
# `mpirun -np 2` and as two merged shards, and writes each output's sha256 to DIR/manifest; it
# also keeps checkpoints and shard parts in DIR. `check DIR` renders the same with the current
# build, compares with DIR/manifest, and resumes DIR's checkpoints and parts (written by the
# recording build) to the hashes of uninterrupted renders. Run `record` before the change (on a
# build of the old commit), `check` after; exits 1 on any difference.
#
#   bench/bit_identity.sh record /tmp/bits           # before the change
#   bench/bit_identity.sh check /tmp/bits            # after it
#   options: --build-dir DIR (default build), --no-build, --spp N (default 2), --size WxH
#            (default 48x40), --no-mpi, --scenes a,b (names as listed in DIR/manifest: the scene
#            file's path)
# About 5 minutes on 2 cores (the displaced sphere's 10M-triangle mesh is made once, into the
# build's bench-work folder, as bench/run.sh makes it).
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/lib.sh

mode="${1:-}"
out="${2:-}"
[[ "$mode" == record || "$mode" == check ]] && [ -n "$out" ] || {
  sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}
shift 2
build_dir=build build=1 spp=2 size=48x40 mpi=1 only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build_dir="$2"; shift ;;
    --no-build) build=0 ;;
    --spp) spp="$2"; shift ;;
    --size) size="$2"; shift ;;
    --no-mpi) mpi=0 ;;
    --scenes) only="$2"; shift ;;
    *) echo "bit_identity: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
[ "$build" = 1 ] && BUILD_DIR="$build_dir" scripts/build.sh candela_cli candela_make_mesh >/dev/null
candela="$build_dir/candela"
work_dir="$build_dir/bench-work"
mkdir -p "$out" "$work_dir"
out=$(cd "$out" && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun_flags=(-np 2 --oversubscribe --mca pml ob1 --mca btl self,vader)
have_mpi=0
[ "$mpi" = 1 ] && command -v mpirun >/dev/null && have_mpi=1

# The scenes: every scene file of scenes/ (but included pbrt fragments) and bench/scenes/.
scenes=()
while IFS= read -r f; do scenes+=("$f"); done < <(
  find scenes -name '*.json' -o -name '*.pbrt' | grep -v '/geometry/' | sort
  for s in "${bench_all_scenes[@]}"; do echo "bench:$s"; done)

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
manifest="$tmp/manifest"
: >"$manifest"
failures=0

hash_of() { sha256sum "$1" | cut -d' ' -f1; }
# Records (or checks) the hash of file $2 under the name $1.
note() {
  local name="$1" file="$2" h
  h=$(hash_of "$file")
  echo "$name $h" >>"$manifest"
  if [ "$mode" = check ]; then
    local want
    want=$(awk -v n="$name" '$1 == n {print $2}' "$out/manifest")
    if [ -z "$want" ]; then
      echo "  new (not in the recorded manifest): $name"
    elif [ "$want" != "$h" ]; then
      echo "  DIFFERS: $name" >&2
      failures=$((failures + 1))
    fi
  fi
}
run() { "$@" >"$tmp/log" 2>&1 || { echo "bit_identity: failed: $*" >&2; cat "$tmp/log" >&2; exit 1; }; }

for entry in "${scenes[@]}"; do
  if [[ "$entry" == bench:* ]]; then
    name="${entry#bench:}"
    prepare_scene "$name" || continue
    file=$(scene_file "$name")
    label="bench/scenes/$name"
  else
    file="$entry"
    label="$entry"
  fi
  if [ -n "$only" ] && ! [[ ",$only," == *",$label,"* ]]; then continue; fi
  echo "$label"
  for transport in rgb spectral; do
    common=(--spp "$spp" --resolution "$size" --"$transport")
    key="$label:$transport"
    run "$candela" render "$file" "${common[@]}" --threads 2 -o "$tmp/one.exr" -o "$tmp/one.png"
    note "$key:one.exr" "$tmp/one.exr"
    note "$key:one.png" "$tmp/one.png"
    run "$candela" render "$file" "${common[@]}" --shard 1/2 -o "$tmp/p1.ckpt"
    run "$candela" render "$file" "${common[@]}" --shard 2/2 -o "$tmp/p2.ckpt"
    run "$candela" merge "$tmp/p1.ckpt" "$tmp/p2.ckpt" -o "$tmp/merged.exr"
    note "$key:merged.exr" "$tmp/merged.exr"
    if [ "$have_mpi" = 1 ]; then
      run mpirun "${mpirun_flags[@]}" "$candela" render "$file" "${common[@]}" --threads 1 -o "$tmp/mpi.exr"
      note "$key:mpi.exr" "$tmp/mpi.exr"
    fi
  done
done

# Adaptive sampling, a noise target and every AOV layer (the film's statistics travel through
# passes, ranks, parts and checkpoints), on the Cornell box.
if [ -z "$only" ]; then
  box=bench/scenes/cornell-box.json
  echo "$box (adaptive, target, AOVs)"
  aovs=albedo,normal,depth,position,variance,spp
  variants=("adaptive:--noise-threshold 0.05 --min-spp 4 --spp 64 --aov $aovs"
            "target:--target-error 0.02 --spp 64")
  for v in "${variants[@]}"; do
    vname="${v%%:*}"
    read -r -a flags <<<"${v#*:}"
    key="$box:$vname"
    run "$candela" render "$box" --resolution "$size" "${flags[@]}" --threads 2 -o "$tmp/one.exr"
    note "$key:one.exr" "$tmp/one.exr"
    if [ "$vname" = adaptive ]; then
      run "$candela" render "$box" --resolution "$size" "${flags[@]}" --shard 1/2 -o "$tmp/p1.ckpt"
      run "$candela" render "$box" --resolution "$size" "${flags[@]}" --shard 2/2 -o "$tmp/p2.ckpt"
      run "$candela" merge "$tmp/p1.ckpt" "$tmp/p2.ckpt" -o "$tmp/merged.exr"
      note "$key:merged.exr" "$tmp/merged.exr"
    fi
    if [ "$have_mpi" = 1 ]; then
      run mpirun "${mpirun_flags[@]}" "$candela" render "$box" --resolution "$size" "${flags[@]}" --threads 1 -o "$tmp/mpi.exr"
      note "$key:mpi.exr" "$tmp/mpi.exr"
    fi
  done

  # Checkpoints and parts across the change: `record` writes them at 4 spp, `check` resumes
  # them (as the recording build wrote them) to 8 spp and compares with an uninterrupted render.
  echo "$box (resume across builds)"
  res=(--resolution "$size" --noise-threshold 0.05 --min-spp 4 --aov albedo,variance)
  if [ "$mode" = record ]; then
    run "$candela" render "$box" "${res[@]}" --spp 4 --checkpoint "$out/box.ckpt" -o "$tmp/ck.exr"
    run "$candela" render "$box" "${res[@]}" --spp 4 --shard 1/2 -o "$out/part1.ckpt"
    run "$candela" render "$box" "${res[@]}" --spp 4 --shard 2/2 -o "$out/part2.ckpt"
    run "$candela" render "$box" "${res[@]}" --spp 8 -o "$tmp/full.exr"
    note "resume:full.exr" "$tmp/full.exr"
  else
    run "$candela" render "$box" "${res[@]}" --spp 8 --resume "$out/box.ckpt" --checkpoint "$tmp/box.ckpt" \
      -o "$tmp/resumed.exr"
    note "resume:full.exr" "$tmp/resumed.exr"
    run "$candela" render "$box" "${res[@]}" --spp 8 --shard 1/2 --resume "$out/part1.ckpt" -o "$tmp/p1.ckpt"
    run "$candela" render "$box" "${res[@]}" --spp 8 --shard 2/2 --resume "$out/part2.ckpt" -o "$tmp/p2.ckpt"
    run "$candela" merge "$tmp/p1.ckpt" "$tmp/p2.ckpt" -o "$tmp/merged.exr"
    note "resume:full.exr" "$tmp/merged.exr"
  fi
fi

if [ "$mode" = record ]; then
  cp "$manifest" "$out/manifest"
  echo "bit_identity: recorded $(wc -l <"$manifest") hashes in $out/manifest"
  exit 0
fi
checked=$(wc -l <"$manifest")
if [ "$failures" -gt 0 ]; then
  echo "bit_identity: $failures of $checked outputs differ from $out/manifest" >&2
  exit 1
fi
echo "bit_identity: all $checked outputs bit-identical to $out/manifest"
