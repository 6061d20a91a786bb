#!/usr/bin/env python3
"""Catch2 test names hold no ';': catch_discover_tests gives CTest a name cut at its first ';',
whose filter then matches no test case, so the test passed without running (8 did). A template
test case's name holds no escaped comma ('\\,', which a TEST_CASE name needs): its instances'
names ("name - Kinds - 0") keep the backslash, which their CTest filter then does not match, so
they too passed without running (found in session 19); a plain ',' works there.
Usage: check_test_names.py SOURCE_DIR"""
import pathlib
import re
import sys

NAME = re.compile(r'\b(TEST_CASE|TEMPLATE_TEST_CASE|TEMPLATE_LIST_TEST_CASE)\s*\(\s*"([^"]*)"')

bad = []
for path in sorted((pathlib.Path(sys.argv[1]) / "tests").rglob("*.cpp")):
    for match in NAME.finditer(path.read_text(encoding="utf-8")):
        if ";" in match.group(2):
            bad.append("%s: %s (a ';')" % (path, match.group(2)))
        if match.group(1) != "TEST_CASE" and "\\\\," in match.group(2):
            bad.append("%s: %s (an escaped ',' in a template test case)" % (path, match.group(2)))
for line in bad:
    print("test name CTest would not run:", line)
sys.exit(1 if bad else 0)
