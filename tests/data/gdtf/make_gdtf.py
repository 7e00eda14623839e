#!/usr/bin/env python3
"""Zips a test fixture's description.xml into a .gdtf (a GDTF file is a zip with description.xml
at its root): make_gdtf.py tests/data/gdtf/hex7_wash.xml OUT.gdtf"""
import sys
import zipfile

with zipfile.ZipFile(sys.argv[2], "w", zipfile.ZIP_DEFLATED) as z:
    z.write(sys.argv[1], "description.xml")
