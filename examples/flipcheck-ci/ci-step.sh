#!/bin/sh
# An engine's CI step: the motion file its run wrote ($1), judged. npx flipcheck judge exits 3
# when the motion fails (2 when it cannot be judged): with set -e the step fails, and the job.
set -eu
npx --no-install flipcheck judge book-intermediate-0.05 "${1:-motion.csv}" -o flipcheck-out
echo "the engine's motion passes book-intermediate-0.05"
