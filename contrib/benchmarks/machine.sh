#!/usr/bin/env bash
# One line naming the machine a measurement ran on, for the reporting
# scripts (throughput, MPI scaling, pair contention): CPU model, cores,
# load average and UTC time. Timings differ by 2x and more between the
# machines this project runs on (doc/performance.md, "Machines"),
# so a figure without its machine cannot be compared.
field() { lscpu 2>/dev/null | sed -n "s/^$1: *//p" | head -1; }
mhz=$(awk -F': ' '/^cpu MHz/ { printf "%.0f MHz", $2; exit }' /proc/cpuinfo)
echo "machine: $(field 'Model name') (family $(field 'CPU family'), model $(field 'Model')${mhz:+, $mhz}), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%Y-%m-%dT%H:%M:%SZ)"
