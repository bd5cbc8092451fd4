"""The checks of the parameters a call passes by reference (docs/scl.md §3.7): the in/outs of an
FC and of an FB the FMU's FB uses, and an FC's ARRAY[*] inputs and outputs. S7 passes each
the caller's variable itself: the argument is a variable of the parameter's type (an ARRAY[*]
takes any ARRAY of its element type and number of dimensions), never an expression."""

from __future__ import annotations

from . import ast as A
from . import types as T
from .cnames import by_reference
from .diagnostics import Code, refuse


class InOuts:
    """The checks of the arguments passed by reference (a mixin of checks.Checker)."""

    @staticmethod
    def references(unit) -> list[A.VarDecl]:
        """The parameters of the block `unit` (a Checker) passed by reference, in the order of
        their declaration."""
        return [d for d in unit.block.decls if by_reference(d, unit)]

    def reference_argument(self, formal: A.VarDecl, actual, callee: str):
        """The argument of the parameter `formal` (of the block callee) passed by reference."""
        what = f"{callee}'s {formal.section} {formal.name}"
        if not isinstance(actual, A.VarRef):
            refuse(
                Code.PARAMETER,
                actual,
                f"{what} is passed by reference: it takes a variable, not a value",
            )
        t = self.variable(actual, write=formal.section != A.Section.INPUT)
        if actual.path is None:
            refuse(
                Code.PARAMETER,
                actual,
                f"{what} is passed by reference: it takes a variable, member or element, not "
                "an instance's or a DTL's member",
            )
        for step in actual.path:
            if step[0] == "bit":
                refuse(
                    Code.PARAMETER,
                    actual,
                    f"{what} is passed by reference: it takes no bit (.%X) of a variable",
                )
            if step[0] == "index" and not all(isinstance(x, A.Literal) for x in step[1]):
                refuse(
                    Code.UNSUPPORTED,
                    actual,
                    f"{what}: an element at a run-time index passed by reference is not "
                    "supported yet (docs/scl.md §6); copy it through a VAR_TEMP",
                )
        want = formal.type
        if isinstance(want, T.ArrayType) and want.dims is None:
            fits = (
                isinstance(t, T.ArrayType)
                and t.element == want.element
                and t.dimensions == want.rank
            )
        else:
            fits = t == want
        if not fits:
            refuse(
                Code.PARAMETER,
                actual,
                f"{what} is a {want}; '{actual.name}' is a {t} (S7 passes it by reference: "
                "the same type)",
            )
