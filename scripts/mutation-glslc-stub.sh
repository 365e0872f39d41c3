#!/bin/sh
# Stands in for glslc in the mutation run's scratch build (scripts/mutation-test.py): the GPU
# tests do not run there, so the shaders need not be compiled; the SPIR-V include gets one word.
# glslc is called as: glslc ... <shader> -o <out>
while [ $# -gt 0 ]; do
    if [ "$1" = "-o" ]; then out="$2"; shift; fi
    shift
done
echo "0x07230203" > "$out"
