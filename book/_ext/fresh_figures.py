"""Keep executed pages in step with physics_figures (placeholder, written below)."""


def setup(app):
    return {"parallel_read_safe": True}
