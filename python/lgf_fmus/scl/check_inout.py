"""The checks of the calls of user FCs and of the parameters a call passes by reference
(docs/scl.md §3.7): the in/outs of an FC and of an FB the FMU's FB uses, and an FC's ARRAY[*]
inputs and outputs. S7 passes each the caller's variable itself: the argument is a variable of
the parameter's type (an ARRAY[*] takes any ARRAY of its element type and number of
dimensions), never an expression."""

from __future__ import annotations

from . import ast as A
from . import types as T
from .cnames import by_reference
from .diagnostics import Code, refuse


class InOuts:
    """The checks of an FC's call and of the arguments passed by reference (a mixin of
    checks.Checker)."""

    def fc_call(self, c: A.Call, unit, statement: bool):
        """A call of a user FC (docs/scl.md §3.6): every input given, by name or in the order of
        their declaration; outputs by name (=>), each to a variable of the output's type."""
        fc = unit.block
        refs = {d.name.upper(): d for d in self.references(unit)}
        ins = [d for d in fc.decls if d.section == A.Section.INPUT and d.name.upper() not in refs]
        outs = {
            d.name.upper(): d
            for d in fc.decls
            if d.section == A.Section.OUTPUT and d.name.upper() not in refs
        }
        in_names = [d.name.upper() for d in ins]
        listed = ", ".join(d.name for d in ins) or "none"
        values, targets, passed = {}, {}, {}
        positional = [a for a in c.args if a.name is None]
        if positional and len(positional) != len(c.args):
            refuse(
                Code.PARAMETER, c, f'"{fc.name}": name every parameter (a := ..., b => ...) or none'
            )
        if positional:
            if len(positional) != len(ins):
                refuse(
                    Code.PARAMETER,
                    c,
                    f'"{fc.name}" takes {len(ins)} inputs ({listed}), not {len(positional)}',
                )
            values = dict(zip(in_names, (a.value for a in positional)))
        for arg in c.args if not positional else []:
            key = arg.name.upper()
            if key in values or key in targets or key in passed:
                refuse(Code.PARAMETER, arg, f"\"{fc.name}\": '{arg.name}' is given twice")
            ref = refs.get(key)
            if ref is not None and (arg.target is None) == (ref.section != A.Section.OUTPUT):
                passed[key] = arg.value if arg.target is None else arg.target
            elif arg.target is None:
                if key not in in_names:
                    refuse(
                        Code.PARAMETER,
                        arg,
                        f"\"{fc.name}\" has no input '{arg.name}' (inputs: {listed})",
                    )
                values[key] = arg.value
            else:
                if key not in outs:
                    refuse(
                        Code.PARAMETER,
                        arg,
                        f"\"{fc.name}\" has no output '{arg.name}' "
                        f"(outputs: {', '.join(d.name for d in outs.values()) or 'none'})",
                    )
                targets[key] = arg.target
        missing = [d.name for d in ins if d.name.upper() not in values]
        if missing:
            refuse(
                Code.PARAMETER,
                c,
                f'"{fc.name}" needs {", ".join(missing)}: an FC has no instance data, so '
                "every input is given in every call",
            )
        missing = [d.name for key, d in refs.items() if key not in passed]
        if missing:
            refuse(
                Code.PARAMETER,
                c,
                f'"{fc.name}" needs {", ".join(missing)}: S7 passes them by reference, so '
                "every call gives them",
            )
        for d in ins:
            v = values[d.name.upper()]
            self.expr(v)
            self.coerce(v, d.type, f'"{fc.name}"\'s input {d.name}')
        for key, d in refs.items():
            self.reference_argument(d, passed[key], f'"{fc.name}"')
        for key, target in targets.items():
            t = self.variable(target, write=True)
            if any(step[0] == "bit" for step in target.path):
                refuse(
                    Code.PARAMETER,
                    target,
                    f'"{fc.name}"\'s output {outs[key].name} goes to a variable, member or '
                    "element, not to a bit (.%X) or a slice (.%B): assign it through a VAR_TEMP",
                )
            if t != outs[key].type:
                refuse(
                    Code.PARAMETER,
                    target,
                    f'"{fc.name}"\'s output {outs[key].name} is a {outs[key].type}; '
                    f"'{target.name}' is a {t} (an FC's output goes to a variable of its type)",
                )
        if unit.return_type is None and not statement:
            refuse(
                Code.STATEMENT,
                c,
                f'"{fc.name}" is a FUNCTION : Void, it has no value: call it as a statement',
            )
        c.unit = unit
        c.inputs = [values[n] for n in in_names]
        c.outputs = [targets.get(key) for key in outs]
        c.references = [(d, passed[key]) for key, d in refs.items()]
        c.type = unit.return_type
        return c.type

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
                    f"{what} is passed by reference: it takes no bit (.%X) or slice (.%B1) "
                    "of a variable",
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
