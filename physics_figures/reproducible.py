"""The date every built file carries instead of "now" (matplotlib's SVG and PDF stamps, the
PDFs' dates and ids, the offline zip's entries), so the same source gives the same files.

The Makefile exports SOURCE_DATE_EPOCH with this value (tests/no_site/test_house.py checks that they
agree); a script run on its own, outside make, reads this constant."""

from __future__ import annotations

import os

#: 2026-01-01 00:00 UTC, in seconds since the epoch.
SOURCE_DATE_EPOCH = 1767225600


def source_date_epoch() -> int:
    """The SOURCE_DATE_EPOCH the environment sets (make exports it), else this module's."""
    return int(os.environ.get("SOURCE_DATE_EPOCH", SOURCE_DATE_EPOCH))
