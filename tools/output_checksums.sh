#!/usr/bin/env bash
# Checksums of the program's outputs on every mesh of a folder, for several option sets:
# a refactoring that must not change results is checked by comparing two runs' lists.
#   bash tools/output_checksums.sh PROGRAM MESH_FOLDER > sums.txt
set -euo pipefail
program=$1
meshes=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
option_sets=(
  "--degree 4"
  "--degree 1 --s 1"
  "--degree 2 --s -1"
  "--degree 4 --align curvature --feature-angle 35"
  "--degree 6 --constrain-boundary tangent"
  "--on faces --degree 4"
  "--on faces --degree 4 --feature-angle 35"
  "--on faces --degree 4 --cancel-singularities 0.07"
  "--on faces --degree 4 --align curvature"
)
outputs=(directions.txt singularities.txt field.vtu markers.vtk field.ply list.txt lines.vtp repaired.off
         picture.png run.json)
# A face field's outputs (what quad meshers read, and the pictures).
face_fields() {
  local mesh=$1 options=$2
  # shellcheck disable=SC2086
  if ! "$program" "$mesh" $options --quiet --json-file "$work/run.json" --rosy "$work/field.rosy" \
      --sharp "$work/field.sharp" --rawfield "$work/field.rawfield" --sing "$work/field.sing" \
      --matching "$work/field.matching" --singularities "$work/singularities.txt" --vtk "$work/field.vtu" \
      --vtk-singularities "$work/markers.vtk" --streamlines "$work/lines.vtp" --mesh-out "$work/repaired.off" \
      --png "$work/picture.png" > /dev/null 2> "$work/error.txt"; then
    echo "$(basename "$mesh") [$options] refused: $(head -c 120 "$work/error.txt")"
    return
  fi
  sed -E -i 's/"timings_ms":\{[^}]*\}//; s/"io_ms":[-0-9.e+]*//' "$work/run.json"
  for output in run.json field.rosy field.sharp field.rawfield field.sing field.matching singularities.txt \
      field.vtu markers.vtk lines.vtp repaired.off picture.png; do
    [ -e "$work/$output" ] || { echo "$(basename "$mesh") [$options] $output absent"; continue; }
    echo "$(basename "$mesh") [$options] $output $(sha256sum < "$work/$output" | cut -c1-16)"
  done
}

for mesh in "$meshes"/*.off; do
  for set_index in "${!option_sets[@]}"; do
    rm -f "$work"/*
    cross_field_files=()
    case "${option_sets[$set_index]}" in
      "--degree 4"*) cross_field_files=(--rosy "$work/field.rosy" --ffield "$work/field.ffield") ;;
      "--on faces"*)
        face_fields "$mesh" "${option_sets[$set_index]}"
        continue ;;
    esac
    # shellcheck disable=SC2086
    if ! "$program" "$mesh" ${option_sets[$set_index]} --quiet "${cross_field_files[@]}" --json-file "$work/run.json" \
        --directions "$work/directions.txt" --singularities "$work/singularities.txt" \
        --vtk "$work/field.vtu" --vtk-singularities "$work/markers.vtk" --ply "$work/field.ply" \
        --singularity-list "$work/list.txt" --streamlines "$work/lines.vtp" \
        --mesh-out "$work/repaired.off" --png "$work/picture.png" > /dev/null 2> "$work/error.txt"; then
      echo "$(basename "$mesh") [${option_sets[$set_index]}] refused: $(head -c 120 "$work/error.txt")"
      continue
    fi
    # the JSON without its timings
    sed -E -i 's/"timings_ms":\{[^}]*\}//; s/"io_ms":[-0-9.e+]*//' "$work/run.json"
    [ ${#cross_field_files[@]} -eq 0 ] || outputs_here=("${outputs[@]}" field.rosy field.ffield)
    [ ${#cross_field_files[@]} -ne 0 ] || outputs_here=("${outputs[@]}")
    for output in "${outputs_here[@]}"; do
      [ -e "$work/$output" ] || { echo "$(basename "$mesh") [${option_sets[$set_index]}] $output absent"; continue; }
      echo "$(basename "$mesh") [${option_sets[$set_index]}] $output $(sha256sum < "$work/$output" | cut -c1-16)"
    done
  done
done
