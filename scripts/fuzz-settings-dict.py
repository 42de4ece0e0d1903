#!/usr/bin/env python3
"""Writes fuzz/settings.dict, the libFuzzer dictionary of fuzz_settings, from
the settings table: every section and key as open and close tags, every
choice of an enum or name-list key, then XML syntax and typical values.

  scripts/fuzz-settings-dict.py build/cic > fuzz/settings.dict

Test FuzzDictionary.SettingsDictionaryHasEveryKeyAndChoice fails when a key
is added to the table and this is not run again."""
import re
import subprocess
import sys

SYNTAX = ['<?xml version=\\"1.0\\" encoding=\\"UTF-8\\"?>', "<!--", "-->", "<![CDATA[", "]]>", "&amp;", "&#10;",
          "/>", " ", "0", "1", "-1", "1e308", "nan", "inf", "R0", "R1", "R2"]


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: fuzz-settings-dict.py CIC")
    keys = subprocess.run([sys.argv[1], "settings", "--keys"], check=True, capture_output=True, text=True).stdout
    tags, values = ["settings"], []
    for row in keys.splitlines():
        m = re.match(r"\| `([A-Za-z0-9_]+)\.([A-Za-z0-9_]+)` \| `[^`]*` \| (.*?) \| ", row)
        if not m:
            continue
        section, key, allowed = m.groups()
        tags += [section, key]
        c = re.match(r"(?:one of|space-separated distinct names from): (.*)", allowed)
        if c:
            for choice in c.group(1).split(", "):
                values += choice.split("\\|")
    print("# libFuzzer dictionary for fuzz_settings, written by scripts/fuzz-settings-dict.py from")
    print("# `cic settings --keys`: every section and key, every choice, XML syntax and typical values.")
    seen = set()
    for t in tags:
        if t not in seen:
            seen.add(t)
            print(f'open_{t}="<{t}>"')
            print(f'close_{t}="</{t}>"')
    for v in SYNTAX + values:
        if v not in seen:
            seen.add(v)
            print(f'"{v}"')


if __name__ == "__main__":
    main()
