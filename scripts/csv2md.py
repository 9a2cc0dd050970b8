#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""Print a results CSV as a markdown table (for the README), optionally only some columns.
Usage: scripts/csv2md.py bench/results/NAME.csv [column ...]"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
cols = sys.argv[2:] or list(rows[0])
print("| " + " | ".join(cols) + " |")
print("|" + "---|" * len(cols))
for r in rows:
    print("| " + " | ".join(r.get(c, "") for c in cols) + " |")
