"""Checking a computed value against a number the notes print."""


def assert_rounds_to(value, printed, sig_figs):
    """value rounded to sig_figs significant figures is the number the notes print."""
    printed_text = f"{printed:.{sig_figs - 1}e}"
    assert float(printed_text) == printed, f"{printed} has more than {sig_figs} s.f."
    shown = f"{float(value):.{sig_figs - 1}e}"
    assert shown == printed_text, (
        f"{value!r} rounds to {shown} at {sig_figs} s.f., but the notes print {printed}")
