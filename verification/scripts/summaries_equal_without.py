#!/usr/bin/env python3
"""Field-for-field comparison of the `summary.json` files under two output trees (as written by
`verification/scripts/bitwise_outputs.sh OLD NEW WORK`: WORK/old and WORK/new), leaving out the fields that
measure the machine and the fields named on the command line: a change that adds summary fields is
bitwise everywhere else when this prints "0 differ".

    python3 verification/scripts/summaries_equal_without.py WORK/old WORK/new FIELD [FIELD ...]

Floats are compared exactly (as parsed from the JSON text, which round-trips every f64). Exit 1 if any
summary differs or is missing on the new side.
"""
import json
import sys
from pathlib import Path

MACHINE = {"wall_time_s", "node_steps_per_second", "cpu_time_s", "cpu_node_steps_per_second"}


def strip(value, drop):
    if isinstance(value, dict):
        return {k: strip(v, drop) for k, v in value.items() if k not in drop}
    if isinstance(value, list):
        return [strip(v, drop) for v in value]
    return value


def main() -> int:
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    old, new, drop = Path(sys.argv[1]), Path(sys.argv[2]), MACHINE | set(sys.argv[3:])
    same = differ = 0
    for f in sorted(old.rglob("summary.json")):
        g = new / f.relative_to(old)
        if not g.is_file() or strip(json.loads(f.read_text()), drop) != strip(json.loads(g.read_text()), drop):
            print(f"differs: {f.relative_to(old)}")
            differ += 1
        else:
            same += 1
    print(f"{same} summaries equal field for field without {sorted(set(sys.argv[3:]))}, {differ} differ")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
