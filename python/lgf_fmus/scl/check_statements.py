"""The checks' third pass (docs/scl.md §3.4, §3.6, §3.7): statements and flow. Every
statement of a block in order: an assignment to a variable it may write, a condition that is a
BOOL, CASE labels of the selector's range and none twice, a FOR variable and its bounds, EXIT and
CONTINUE in a loop, a call of an FB instance with its parameters. Each expression is typed by
the expressions' checks (check_expressions.py); an error ends its statement and the next one is
checked."""

from __future__ import annotations

from . import ast as A
from . import types as T
from .diagnostics import Code, refuse
from .types import K


def nested(s: A.Stmt) -> list[list[A.Stmt]]:
    """The statement lists a statement holds (its branches, its body)."""
    if isinstance(s, A.If):
        return [body for _, body in s.branches] + [s.otherwise or []]
    if isinstance(s, A.Case):
        return [body for _, body in s.branches] + [s.otherwise or []]
    if isinstance(s, (A.For, A.While, A.Repeat, A.Region)):
        return [s.body]
    return []


class Statements:
    """The pass over a block's statements (a mixin of checks.Checker)."""

    def statements(self, body: list[A.Stmt]):
        for s in body:
            self.attempt(self.statement, s)

    def statement(self, s: A.Stmt):
        if isinstance(s, A.Assign):
            self.assign(s)
        elif isinstance(s, A.CallStmt):
            self.call_statement(s.call)
        elif isinstance(s, A.If):
            for condition, body in s.branches:
                self.attempt(self.condition, condition, "IF")
                self.statements(body)
            self.statements(s.otherwise or [])
        elif isinstance(s, A.Case):
            self.attempt(self.case_labels, s)
            for _, body in s.branches:
                self.statements(body)
            self.statements(s.otherwise or [])
        elif isinstance(s, A.For):
            self.attempt(self.for_header, s)
            self.loop(s.body)
        elif isinstance(s, A.While):
            self.attempt(self.condition, s.condition, "WHILE")
            self.loop(s.body)
        elif isinstance(s, A.Repeat):
            self.loop(s.body)
            self.attempt(self.condition, s.condition, "UNTIL")
        elif isinstance(s, A.Jump):
            if s.kind != "RETURN" and not self.loops:
                refuse(Code.STATEMENT, s, f"{s.kind} outside FOR, WHILE or REPEAT")
        elif isinstance(s, A.Region):
            self.statements(s.body)

    def jumps(self, body: list[A.Stmt]):
        """GOTO and its jump labels (docs/scl.md §3.4 [S7-GOTO]): each label once in the block,
        each GOTO to a label of its own statement list or of one around it (a REGION is no
        list of its own), never into an IF, CASE or loop; a label before its GOTO makes a
        loop, which the cycle watchdog counts."""
        labels: dict[str, A.Label] = {}
        for s in A.nodes(body):
            if isinstance(s, A.Label):
                first = labels.get(s.name.lower())
                if first is not None:
                    self.attempt(
                        refuse,
                        Code.DUPLICATE,
                        s,
                        f"the jump label '{s.name}' stands twice in the block",
                        [(first.loc, "first here")],
                    )
                labels.setdefault(s.name.lower(), s)

        def own(statements):  # the labels of a list, a REGION's among them
            for s in statements:
                if isinstance(s, A.Label):
                    yield s.name.lower()
                elif isinstance(s, A.Region):
                    yield from own(s.body)

        def walk(statements, visible):
            visible = visible | set(own(statements))
            for s in statements:
                if isinstance(s, A.Goto):
                    self.attempt(self.goto, s, labels, visible)
                for inner in nested(s):
                    walk(inner, visible)

        walk(body, frozenset())

    def goto(self, s: A.Goto, labels: dict, visible):
        target = labels.get(s.label.lower())
        if target is None:
            refuse(Code.UNDECLARED, s, f"GOTO {s.label}: the block has no jump label '{s.label}'")
        if s.label.lower() not in visible:
            refuse(
                Code.STATEMENT,
                s,
                f"GOTO {s.label}: a jump into an IF, CASE or loop (docs/scl.md §3.4 [S7-GOTO]); "
                "jump to a label of the GOTO's own statements or of those around them",
                [(target.loc, "the label")],
            )
        target.used = True
        s.backward = (target.loc.line, target.loc.column) < (s.loc.line, s.loc.column)

    def case_labels(self, s: A.Case):
        """The selector and the labels of a CASE: an integer or bit string, literal labels of its
        range, no two overlapping."""
        t = self.expr(s.selector)
        if isinstance(t, T.Untyped):
            self.coerce(s.selector, T.DINT, "the CASE selector")
            t = T.DINT
        if not isinstance(t, T.Elementary) or t.kind not in (K.INT, K.BITS):
            refuse(
                Code.OPERAND,
                s.selector,
                f"the CASE selector must be an integer or bit string, not {t}",
            )
        seen = []
        for labels, _ in s.branches:
            for low, high in labels:
                if not (T.fits(low, t) and T.fits(high, t)) or low > high:
                    refuse(Code.RANGE, s, f"the CASE label {low}..{high} is not a range of {t}")
                for other in seen:
                    if low <= other[1] and other[0] <= high:
                        refuse(
                            Code.DUPLICATE,
                            s,
                            f"the CASE label {low}..{high} overlaps {other[0]}..{other[1]}",
                        )
                seen.append((low, high))

    def for_header(self, s: A.For):
        t = self.variable(s.variable, write=True)
        if s.variable.members:
            refuse(Code.STATEMENT, s.variable, "the FOR variable must be a plain variable")
        if not isinstance(t, T.Elementary) or t.kind != K.INT or not t.signed or t.bits > 32:
            refuse(
                Code.OPERAND, s.variable, f"the FOR variable must be a SINT, INT or DINT, not {t}"
            )
        for part, what in ((s.start, "start"), (s.end, "end"), (s.step, "BY")):
            if part is not None:
                self.expr(part)
                self.coerce(part, t, f"the FOR {what} value")

    def loop(self, body):
        self.loops += 1
        self.statements(body)
        self.loops -= 1

    def condition(self, e, what):
        self.expr(e)
        self.coerce(e, T.BOOL, f"the {what} condition")

    def assign(self, s: A.Assign):
        t = self.variable(s.target, write=True)
        if isinstance(t, T.ArrayType) and t.dims is None and self.block is not self.program.top:
            refuse(
                Code.UNSUPPORTED,
                s.target,
                f"'{s.target.name}' is an {t}: an ARRAY[*] is assigned element by element",
            )
        value = s.value
        if s.op != ":=":  # x op= e is x := x op e (lower.py makes it so after the checks)
            value = s.operation = A.Binary(s.loc, s.op[0], s.target, s.value)
        self.expr(value)
        self.coerce(value, t, f"the assignment to '{s.target.name}'")

    def call_statement(self, c: A.Call):
        d = None if c.quoted else self.names.get(c.callee.lower())
        if c.method is not None and not c.local or c.quoted and self.is_db(c.callee):
            d = self.global_db(c.callee, c, c.method)
        elif c.method is not None and d is not None and getattr(d.type, "name", "") != c.method:
            refuse(Code.INSTANCE, c, f"#{c.callee}.{c.method}(...): '{c.callee}' is no IEC_TIMER")
        if d is not None and not c.local and not isinstance(d.type, T.FbType):
            d = None  # SHL(...) in a block with a variable shl: the function
        if d is None or d.section == A.Section.RETURN:
            if c.local and d is None:
                refuse(Code.UNDECLARED, c, f"'{c.callee}' is not declared in {self.block.name}")
            unit = self.user_unit(c)
            if unit is not None:
                self.fc_call(c, unit, statement=True)
                return
            self.call(c, statement=True)  # a value dropped (QRY_CINT(...)), or none
            return
        if c.index is not None:  # #axes[#i](...): an element of an ARRAY of instances (§3.7)
            c.instance = A.VarRef(c.loc, d.name, [c.index], True)
            fb = self.variable(c.instance)
            if not isinstance(fb, T.FbType):
                refuse(Code.INSTANCE, c, f"'{d.name}[..]' is a {fb}, not an FB instance")
        else:
            if not isinstance(d.type, T.FbType):
                refuse(Code.INSTANCE, c, f"'{d.name}' is a {d.type}, not an FB instance")
            fb = d.type
            c.instance = A.VarRef(c.loc, d.name, [], True)
            c.instance.decl = d
        c.fb = fb
        refs = {}
        if fb.block is not None:
            refs = {d.name.upper(): d for d in self.references(fb.block)}
        seen = set()
        for arg in c.args:
            if arg.name is None:
                refuse(
                    Code.PARAMETER, arg, f"{fb.name} '{d.name}': name the parameters (IN := ...)"
                )
            name = arg.name.upper()
            if name in seen:
                refuse(Code.PARAMETER, arg, f"'{name}' is given twice")
            seen.add(name)
            if arg.target is None and name in refs:
                self.reference_argument(refs[name], arg.value, fb.name)
                c.references.append((refs[name], arg.value))
            elif arg.target is None:
                if name not in fb.inputs:
                    refuse(
                        Code.PARAMETER,
                        arg,
                        f"{fb.name} has no input '{arg.name}' ({', '.join(fb.inputs)})",
                    )
                self.expr(arg.value)
                self.coerce(arg.value, fb.inputs[name], f"{fb.name}'s {name}")
                c.inputs.append((name, arg.value))
            else:
                if name not in fb.outputs:
                    refuse(
                        Code.PARAMETER,
                        arg,
                        f"{fb.name} has no output '{arg.name}' ({', '.join(fb.outputs)})",
                    )
                t = self.variable(arg.target, write=True)
                if not T.implicit(fb.outputs[name], t, self.program.iec_check):
                    refuse(
                        Code.PARAMETER,
                        arg,
                        f"{fb.name}'s {name} is a {fb.outputs[name]}, '{arg.target.name}' a {t}",
                    )
                c.outputs.append((name, arg.target))
        missing = [x.name for key, x in refs.items() if key not in seen]
        if missing:
            refuse(
                Code.PARAMETER,
                c,
                f"{fb.name} '{d.name}' needs {', '.join(missing)}: its in/outs are passed by "
                "reference in every call (docs/scl.md §3.7)",
            )
        c.type = None
