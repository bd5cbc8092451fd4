"""Lowering (docs/scl.md §1): after every check has passed and before the C generation, the
checked tree is rewritten into the simpler forms the C generation takes, so that neither the
checks nor the C generation change the tree on the side:

- a compound assignment `x op= e` becomes `x := x op e`, with the operation the checks typed
  (Assign.operation; its read of x shares the write's place in the C);
- `&` becomes AND;
- a minus sign before a literal is folded into a negative literal (`fold`, which the checks use
  too where a constant is required: initial values, LOWER_BOUND's DIM)."""

from __future__ import annotations

from dataclasses import fields

from . import ast as A

# the checks' links to other parts of the tree and their types: not walked
_LINKS = {"loc", "decl", "type", "operand_type", "operand", "builtin", "unit", "fb"}


def fold(e):
    """-literal is a literal (-32768 is an INT), of the type the checks gave the expression."""
    if isinstance(e, A.Unary) and e.op == "-" and isinstance(e.operand, A.Literal):
        lit = fold(e.operand)
        if lit.kind in ("int", "real", "time"):
            folded = A.Literal(e.loc, lit.kind, "-" + lit.text, -lit.value, lit.type_prefix)
            folded.type = e.type if e.type is not None else lit.type
            return folded
    return e


def _lower(x):
    """x lowered: a node, or a list, tuple or dict of them (lists and dicts in place, as the
    checks' records share them); returns what stands for x."""
    if isinstance(x, list):
        x[:] = [_lower(item) for item in x]
        return x
    if isinstance(x, tuple):
        return tuple(_lower(item) for item in x)
    if isinstance(x, dict):
        for key in x:
            x[key] = _lower(x[key])
        return x
    if not isinstance(x, A.Node):
        return x
    for f in fields(x):
        if f.name not in _LINKS:
            setattr(x, f.name, _lower(getattr(x, f.name)))
    if isinstance(x, A.Assign) and x.operation is not None:
        x.value, x.op = x.operation, ":="
    elif isinstance(x, A.Binary) and x.op == "&":
        x.op = "AND"
    elif isinstance(x, A.Unary):
        return fold(x)
    return x


def lower(program):
    """Lowers the statements of every block the checks have passed (checks.Program.order)."""
    for checker in program.order:
        _lower(checker.block.body)
