#!/usr/bin/env bash
# Regenerates every figure under docs/ from the runs it names:
#
#   docs/validation_speed_vs_error.png  the bundled 3.9 km/s RZ scene at A_res 2, 1, 0.5 and
#                                       0.25 mm and its 3-D quarter at 2 mm, to 400 µs
#                                       (docs/validation.md, "Resolution")
#
# A figure added to docs/ gets its runs and its drawing command here.
#
#   docs/scripts/figures.sh RUNS_DIR
#
# Each run goes to RUNS_DIR/NAME, one thread, with checkpoints; a finished run (its
# summary.json says "complete": true) is not run again and a stopped one resumes from its
# newest checkpoint, so the script can be stopped and started again. On this project's two-core
# machine the runs take about 4.5 h on one thread (0.25 mm RZ about 2.8 h, the 3-D quarter
# about 1.4 h, from the wall times in docs/validation.md); RUNS_DIR belongs outside the repository.
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=${1:?usage: docs/scripts/figures.sh RUNS_DIR}
mkdir -p "$runs"
cargo build --release -p sph-impact
cargo build --release -p sph-examples --example speed_vs_error
bin=target/release/sph-impact

# run NAME SCENE SCALE: the scene at --resolution-scale SCALE into RUNS_DIR/NAME.
run() {
    local dir="$runs/$1"
    # A stopped run also writes summary.json, with "complete": false.
    if grep -q '"complete": true' "$dir/summary.json" 2> /dev/null; then
        echo "$1: finished, kept"
        return
    fi
    local resume=()
    if compgen -G "$dir/checkpoints/step-*.cbor" > /dev/null; then
        resume=(--resume)
    else
        rm -rf "$dir"
    fi
    "$bin" run "$2" --out "$dir" --resolution-scale "$3" --threads 1 --checkpoint "${resume[@]}"
}

rz=examples/scenes/basalt_3.9kms_rz.toml
run rz_2mm "$rz" 0.25
run rz_1mm "$rz" 0.5
run rz_0.5mm "$rz" 1
run rz_0.25mm "$rz" 2
run quarter_2mm examples/scenes/basalt_3.9kms_quarter.toml 0.25

target/release/examples/speed_vs_error \
    "$runs/rz_2mm" "$runs/rz_1mm" "$runs/rz_0.5mm" "$runs/rz_0.25mm" "$runs/quarter_2mm" \
    --plot docs/validation_speed_vs_error.png
echo "written: docs/validation_speed_vs_error.png"
