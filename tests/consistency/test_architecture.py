"""The package's rooms and their order (docs/architecture.md), checked on the imports the code makes.

Every ``import`` and ``from ... import`` in ``src/auxbearing`` counts, those inside functions too: a lazy
import is still a dependency. Two rules: no module imports, directly or round a circle, a module that imports
it back; and no room imports a room above it in :data:`ROOMS`.
"""

from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[2] / "src" / "auxbearing"
#: The rooms from the floor up (docs/architecture.md gives one paragraph to each); a room may import the rooms
#: before it and itself, never one after it.
ROOMS = ("core", "common", "catalog", "bearings", "machine", "analysis", "planar", "campaign", "plots", "report",
         "verify", "experiment", "paper", "cli")


def _modules() -> dict[str, Path]:
    out = {}
    for path in PACKAGE.rglob("*.py"):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        out[name] = path
    return out


def _imports(modules: dict[str, Path]) -> dict[str, set[str]]:
    """Module -> the package's modules it imports (a name imported from a package that is a submodule counts
    as that submodule)."""
    edges: dict[str, set[str]] = {}
    for name, path in modules.items():
        found = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                targets = [f"{node.module}.{a.name}" if f"{node.module}.{a.name}" in modules else node.module
                           for a in node.names]
            else:
                continue
            for target in targets:
                while target and target not in modules:
                    target = target.rpartition(".")[0]
                if target.startswith("auxbearing") and target != name:
                    found.add(target)
        edges[name] = found
    return edges


def _room(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 2 or (len(parts) == 2 and parts[1] in ROOMS) else None


def _circles(edges: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected groups of more than one module (Tarjan), the package's own __init__ left out."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w == "auxbearing":
                continue
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1:
                out.append(sorted(group))

    for v in edges:
        if v not in index and v != "auxbearing":
            visit(v)
    return out


def test_no_module_imports_its_way_back_to_itself():
    assert _circles(_imports(_modules())) == []


def test_every_room_is_named_and_imports_only_the_rooms_below_it():
    edges = _imports(_modules())
    rooms = {_room(m) for m in edges} - {None}
    assert rooms <= set(ROOMS), f"rooms not in ROOMS (docs/architecture.md): {sorted(rooms - set(ROOMS))}"
    upward = sorted(f"{a} -> {b}" for a, targets in edges.items() for b in targets
                    if _room(a) and _room(b) and ROOMS.index(_room(b)) > ROOMS.index(_room(a)))
    assert upward == []


def test_the_architecture_page_has_a_paragraph_for_every_room():
    text = (PACKAGE.parents[1] / "docs" / "architecture.md").read_text(encoding="utf-8")
    missing = [room for room in ROOMS if f"`{room}/`" not in text]
    assert missing == []
