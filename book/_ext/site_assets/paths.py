"""Where this extension's files are, and where it writes in the site."""

from pathlib import Path

HERE = Path(__file__).resolve().parent  # the node scripts beside this file
ASSETS = "site-assets"  # folder under the site's _static/ for what this extension writes
