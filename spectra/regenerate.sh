#!/bin/sh
# Regenerates the shipped target spectra from the library (review the diff, never hand-edit):
#   spectra/regenerate.sh [path/to/freestand]     (default: build/default/freestand)
# Files are at 1.0 g (RG 1.60, EC8, IS 1893) or the stated SDS/SD1; 301 points 0.1-100 Hz.
set -eu
cd "$(dirname "$0")"
exe=${1:-../build/default/freestand}
for pct in 0.5 2 5 7 10; do
  d=$(awk "BEGIN{print $pct/100}")
  "$exe" target --design rg1.60 --pga 1 --damping "$d" --output "rg160-h-${pct}pct-1g.csv"
  "$exe" target --design rg1.60 --pga 1 --damping "$d" --vertical --output "rg160-v-${pct}pct-1g.csv"
done
"$exe" target --design asce7 --sds 1.0 --sd1 0.6 --tl 8 --output asce7-sds1.0-sd1-0.6-tl8.csv
for type in 1 2; do
  for ground in A B C D E; do
    for pct in 5 10; do
      d=$(awk "BEGIN{print $pct/100}")
      "$exe" target --design ec8 --ag 1 --type $type --ground $ground --damping "$d" \
        --output "ec8-type${type}-ground${ground}-${pct}pct-1g.csv"
    done
  done
done
for soil in rock medium soft; do
  "$exe" target --design is1893 --pga 1 --soil $soil --output "is1893-${soil}-5pct-1g.csv"
done
