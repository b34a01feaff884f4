"""The models layer is pure numpy: it never imports matplotlib, and of our own code it
imports only `constants` (DESIGN.md, "three layers, arrows point one way")."""

import ast
import subprocess
import sys
from pathlib import Path

MODELS = Path(__file__).resolve().parents[2] / "physics_figures" / "models"


def test_models_and_scenarios_never_import_matplotlib():
    code = ("import sys, physics_figures.models, physics_figures.scenarios; "
            "print(sorted(m for m in sys.modules if m.split('.')[0] == 'matplotlib'))")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            check=True)
    assert result.stdout.strip() == "[]"


def test_models_import_only_numpy_the_standard_library_and_constants():
    for path in MODELS.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.level == 2:
                assert node.module == "constants", f"{path.name} imports ..{node.module}"
            if isinstance(node, ast.ImportFrom) and node.level == 0:
                assert node.module.split(".")[0] in sys.stdlib_module_names | {"numpy"}, path.name
            if isinstance(node, ast.Import):
                for alias in node.names:
                    assert alias.name.split(".")[0] in sys.stdlib_module_names | {"numpy"}, (
                        f"{path.name} imports {alias.name}")
