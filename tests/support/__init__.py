"""Helpers the test modules share, each defined once here (tests/test_code_layout.py checks
that no test module defines a helper another one defines too). What scripts/ shares with the
tests lives in scripts/ (scripts/browser.py): no script imports a test."""
