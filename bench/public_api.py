#!/usr/bin/env python3
"""Counts each library crate's public API: the items a user of the crate can name.

Reads rustdoc's JSON output (a nightly toolchain: `rustup toolchain install nightly`), which
holds exactly the items reachable from outside the crate, re-exports resolved. Counted: types
(structs, enums, unions, traits, type aliases), functions (free functions, the public methods of
inherent impls and the methods a public trait declares; trait impls' methods are the trait's,
not new API), constants (consts, statics, associated consts), public struct fields, macros. Enum variants are part of
their enum and not counted.

    python3 bench/public_api.py [--target-dir DIR] [CRATE ...]

prints a table, one row per crate (all library crates by default; a dash for one the commit
does not have). Run it at two commits to
compare: each `cargo rustdoc` is a check build, so give it a target dir of its own (the default,
/tmp/public-api-target) to leave the main build's artefacts alone.
"""

import argparse
import collections
import json
import os
import pathlib
import subprocess
import sys

CRATES = [
    "behavior-core", "behavior-data", "behavior-bddl", "behavior-sim", "behavior-forms",
    "behavior-assets", "behavior-sampling", "behavior-robots", "behavior-render",
    "behavior-env", "behavior-catalog", "behavior-motion", "behavior-planning", "behavior-web",
]
KINDS = {
    "struct": "types", "enum": "types", "union": "types", "trait": "types",
    "type_alias": "types", "function": "functions", "constant": "constants",
    "static": "constants", "assoc_const": "constants", "struct_field": "fields",
    "macro": "macros",
}
COLUMNS = ["types", "functions", "constants", "fields", "macros"]


def kind_of(item: dict) -> str:
    """An item's kind: the one key of its `inner`."""
    return next(iter(item["inner"])) if isinstance(item["inner"], dict) else item["inner"]


def count(doc: dict) -> collections.Counter:
    """Public items of the documented crate (crate id 0), by column; a public trait's methods,
    constants and types count as the trait's items."""
    counts = collections.Counter()
    index = doc["index"]
    for item in index.values():
        if item["crate_id"] != 0 or item["visibility"] != "public":
            continue
        kind = kind_of(item)
        if kind in KINDS:
            counts[KINDS[kind]] += 1
        if kind == "trait":
            for member in item["inner"]["trait"]["items"]:
                member_kind = kind_of(index[str(member)])
                column = {"assoc_type": "types"}.get(member_kind, KINDS.get(member_kind))
                if column:
                    counts[column] += 1
    return counts


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--target-dir", default="/tmp/public-api-target")
    parser.add_argument("crates", nargs="*", default=CRATES)
    args = parser.parse_args()
    rows = []
    for crate in args.crates:
        known = subprocess.run(["cargo", "pkgid", "-q", crate], capture_output=True)
        if known.returncode != 0:
            rows.append((crate, None))  # not in this commit's workspace
            continue
        command = [
            "cargo", "+nightly", "rustdoc", "-q", "-p", crate, "--lib", "--",
            "-Z", "unstable-options", "--output-format", "json",
        ]
        result = subprocess.run(command, env={**os.environ, "CARGO_TARGET_DIR": args.target_dir})
        if result.returncode != 0:
            print(f"{crate}: cargo rustdoc failed ({result.returncode})", file=sys.stderr)
            return 1
        path = pathlib.Path(args.target_dir) / "doc" / (crate.replace("-", "_") + ".json")
        counts = count(json.loads(path.read_text()))
        rows.append((crate, counts))
    print("| crate | " + " | ".join(COLUMNS) + " | total |")
    print("|---" * (len(COLUMNS) + 2) + "|")
    totals = collections.Counter()
    for crate, counts in rows:
        if counts is None:
            print(f"| {crate} |" + " — |" * (len(COLUMNS) + 1))
            continue
        totals.update(counts)
        cells = [str(counts[c]) for c in COLUMNS]
        print(f"| {crate} | " + " | ".join(cells) + f" | {sum(counts.values())} |")
    cells = [str(totals[c]) for c in COLUMNS]
    print("| all | " + " | ".join(cells) + f" | {sum(totals.values())} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
