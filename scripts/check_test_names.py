#!/usr/bin/env python3
"""Catch2 test names hold no ';': catch_discover_tests gives CTest a name cut at its first ';',
whose filter then matches no test case, so the test passed without running (8 did).
Usage: check_test_names.py SOURCE_DIR"""
import pathlib
import re
import sys

NAME = re.compile(r'\b(TEST_CASE|TEMPLATE_TEST_CASE|TEMPLATE_LIST_TEST_CASE)\s*\(\s*"([^"]*)"')

bad = []
for path in sorted((pathlib.Path(sys.argv[1]) / "tests").rglob("*.cpp")):
    for match in NAME.finditer(path.read_text(encoding="utf-8")):
        if ";" in match.group(2):
            bad.append("%s: %s" % (path, match.group(2)))
for line in bad:
    print("test name with ';' (CTest would not run it):", line)
sys.exit(1 if bad else 0)
