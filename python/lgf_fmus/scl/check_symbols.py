"""The checks' first pass (docs/scl.md §2, §4, §3.9): symbols and declarations. Every
declaration's name (declared once, none that S7 or the FMU has already, none whose C name
another has), its section (no statics in an FC), the calling OB; the
names a statement uses (a variable, ENO, a DB of the sources, an FC, an FB's instance type);
an FC's return value."""

from __future__ import annotations

import re

from . import ast as A
from . import tags
from . import types as T
from .cnames import field
from .diagnostics import Code, SclError, Silent, refuse

# what no name holds: the C0 and C1 controls, DEL and the Unicode line breaks
CONTROL = re.compile("[\u0000-\u001f\u007f-\u009f\u2028\u2029]")
TIMERS = ("TON", "TOF", "TP")  # what an IEC_TIMER DB runs
# the longest name TIA Portal gives a block, a type or a variable
NAME_LIMIT = 128
# The date and time parameters of an FMU whose program reads the clock (docs/scl.md §3.6)
# what an OB declares (docs/scl.md §3.10): its start information, temporaries and constants
OB_SECTIONS = (A.Section.INPUT, A.Section.TEMP, A.Section.CONSTANT)
DATE_PARAMETERS = ("startDateAndTime", "localTimeOffset")


def identifier(node, name: str):
    """Refuses a name longer than TIA's, or one with a control character; any other character
    may stand in a quoted name (docs/scl.md §3.11 [DEC-NAME-C]: the C mangles it)."""
    if len(name) > NAME_LIMIT:
        refuse(
            Code.NAME,
            node,
            f'"{name[:20]}...": a name of {len(name)} characters (TIA: {NAME_LIMIT} at most)',
        )
    if CONTROL.search(name):
        refuse(Code.NAME, node, f"{name!r}: a name holds no control character (line break, tab)")


def c_name(node, name: str, c: str, taken: dict):
    """Refuses a name whose C name c another name of the same scope (taken: C name -> node) has
    already, as "a.b" and q_a_2e_b have (docs/scl.md §3.11 [DEC-NAME-C])."""
    other = taken.get(c)
    if other is not None:
        refuse(
            Code.NAME,
            node,
            f'"{name}" and "{other.name}" are both {c} in the C: rename one',
            [(other.loc, "declared here")],
        )
    taken[c] = node


class Symbols:
    """The pass over a block's declarations that gives each its name, and the lookups of names
    the later passes make (a mixin of checks.Checker)."""

    def symbols(self):
        for d in list(self.block.decls):
            if not self.attempt(self.declare_name, d):
                d.type = T.ERROR  # its uses end their statements without a second error
        if self.fc and not self.attempt(self.returns):
            self.return_type = T.ERROR

    def declare(self, d: A.VarDecl):
        """A declaration the checks make (a DB of the program, ENO): both passes at once."""
        self.declare_name(d)
        self.declare_type(d)

    def declare_name(self, d: A.VarDecl):
        """The name of a declaration and its section: no name twice, none that S7 or the FMU
        has already, a section this block may have."""
        key = d.name.lower()  # SCL names are case-insensitive
        if key in self.names:
            first = self.names[key].loc
            refuse(
                Code.DUPLICATE, d, f"'{d.name}' is declared twice", [(first, "first declared here")]
            )
        identifier(d, d.name)
        c_name(d, d.name, field(d.name), self.c_names)
        if key == "cycletime":
            refuse(
                Code.RESERVED, d, "'cycleTime' is the FMU's own parameter (docs/behaviour.md §1.1)"
            )
        if key in ("en", "eno"):
            what = "output ENO" if key == "eno" else "input EN"
            refuse(
                Code.RESERVED,
                d,
                f"'{d.name}': S7 gives every block its enable {what}; name it otherwise",
            )
        self.names[key] = d
        if self.block.kind == "ORGANIZATION_BLOCK" and d.section not in OB_SECTIONS:
            refuse(
                Code.DECLARATION,
                d,
                f"the ORGANIZATION_BLOCK {self.block.name} has no instance data and no "
                f"parameters: only its start information (VAR_INPUT), VAR_TEMP and VAR "
                f"CONSTANT, not {d.section} '{d.name}' (docs/scl.md §3.10)",
            )
        if self.fc and d.section.static:
            refuse(
                Code.DECLARATION,
                d,
                f"the FUNCTION {self.block.name} has no instance data, so no statics: "
                f"declare '{d.name}' in VAR_TEMP, or make the block a FUNCTION_BLOCK",
            )
        if d.type_ref is None and d.type_name.upper() in T.OB_NUMBERS:
            self.calling_ob(d)

    def calling_ob(self, d: A.VarDecl):
        """An input of an OB number (OB_CYCLIC: the LGF CI blocks' callOB) in the FB compiled
        into the FMU is no FMI variable: the parameter cycleTime plays the calling OB
        (docs/behaviour.md §1.1). It is a temporary holding its initial value, or 30 (OB30),
        in every call, as if the caller passed the same OB each time (docs/scl.md §4)."""
        if d.section != A.Section.INPUT or self.block is not self.program.top:
            return
        d.section, d.calling_ob = A.Section.TEMP, True
        if d.init is None:
            d.init = A.Literal(d.loc, "int", "30", 30)

    def eno(self, ref: A.VarRef) -> A.VarDecl:
        """ENO, the enable output every block has: a BOOL temporary that starts TRUE and that
        the block may set; the FMU has no EN/ENO, so nothing reads it (docs/scl.md §3.4)."""
        d = A.VarDecl(ref.loc, "ENO", "BOOL", ref.loc, None, A.Section.TEMP)
        d.type = T.BOOL
        d.init = A.Literal(ref.loc, "bool", "TRUE", True, "BOOL")
        d.start = self.initial(d.init, T.BOOL, "ENO")
        self.block.decls.append(d)
        self.names["eno"] = d
        return d

    def decl(self, ref: A.VarRef) -> A.VarDecl:
        if ref.quoted and (ref.name.startswith("%") or self.tag(ref.name) is not None):
            return self.tag_decl(ref)
        d = self.names.get(ref.name.lower())
        if ref.quoted and self.is_db(ref.name):
            d = self.global_db(ref.name, ref)
        if d is None and ref.name.upper() == "ENO":
            d = self.eno(ref)
        if d is None:
            refuse(Code.UNDECLARED, ref, f"'{ref.name}' is not declared in {self.block.name}")
        return d

    def tag(self, name: str):
        """The PLC tag of that name in the program's tag table, or None (docs/scl.md §3.12)."""
        schedule = self.program.schedule
        tags = schedule.tags if schedule is not None else []
        return next((t for t in tags if t.name.lower() == name.lower()), None)

    def tag_decl(self, ref: A.VarRef) -> A.VarDecl:
        """ "Tag" or its absolute address %IW64 as the variable the blocks read and write: an
        %I tag in the process image input PII, a %Q tag in the process image output PIQ, an %M
        tag in itself, each a static of the FMU's FB (docs/scl.md §3.12)."""
        if ref.name.startswith("%"):
            schedule = self.program.schedule
            address = tags.parse_address(ref.name)
            if address is None:
                refuse(Code.SELECTOR, ref, f"{ref.name}: the byte of a bit address takes .0 to .7")
            tag = tags.by_address(schedule.tags if schedule else []).get(address)
            if tag is None:
                refuse(
                    Code.UNDECLARED,
                    ref,
                    f"no tag of the tag table has the address {ref.name} (TIA names each "
                    "address the program uses: give it a row, docs/scl.md §3.12)",
                )
        else:
            tag = self.tag(ref.name)
        # the statics program.py declares for the tags in the FMU's FB, checked before its
        # statements run the OBs
        top = self.program.top_checker
        if tag.area == "M":
            d = top.names[tag.name.lower()]
        else:
            d = top.names["pii" if tag.area == "I" else "piq"]
            if ref.tag is None:  # "Level" is #PII.Level of the FMU's FB
                ref.tag = tag.name
                ref.members.insert(0, tag.name)
        d.db = True  # reached from every block through the call's context, as a DB (§3.9)
        return d

    def global_db(self, name: str, node, method: str | None = None) -> A.VarDecl:
        """The DB `name` of the sources as the FMU holds it: a static of the FB compiled into
        the FMU (in its state, among its locals), made at its first use by any block of the
        program, which reaches it through the call's context. An instance DB of an
        FB ("Motor_DB"(...), "Motor_DB".Q), of an IEC timer ("T_DB".TON(...), which needs no
        DATA_BLOCK: the call names the timer) or a global DB ("Data".x)."""
        key = name.lower()
        d = self.program.db_statics.get(key)
        if d is None:
            top = self.program.top_checker
            try:
                d = top.db_static(name, self.program.dbs.get(key), node)
            except SclError:  # reported once: its other uses end without an error
                poisoned = A.VarDecl(node.loc, name, "", node.loc, None, A.Section.STATIC, db=True)
                poisoned.type = T.ERROR
                self.program.db_statics[key] = poisoned
                raise
            self.program.db_statics[key] = d
        if d.type is T.ERROR:
            raise Silent()
        timer = d.type_name.upper() in TIMERS
        if method is not None and (not timer or d.type_name.upper() != method):
            what = f"an IEC_TIMER DB of {d.type_name}" if timer else f"the DB of {d.type_name}"
            refuse(Code.DB, node, f'"{name}".{method}(...): "{name}" is {what}')
        if method is None and timer and isinstance(node, A.Call):
            refuse(
                Code.DB,
                node,
                f'"{name}" is an IEC_TIMER DB: call it as "{name}".{d.type_name}(...)',
            )
        return d

    def is_db(self, name: str) -> bool:
        """A DB of the sources, or one a block runs an IEC timer on ("T_DB".TON(...))."""
        key = name.lower()
        return key in self.program.dbs or bool(self.timers_on(name))

    def timers_on(self, name: str) -> set[str]:
        """The timers the program's blocks run on the DB `name` ("T_DB".TON(...))."""
        if self.program.timer_dbs is None:  # the whole program's, found once
            self.program.timer_dbs = {}
            for block in self.program.blocks.values():
                for n in A.nodes(block.body):
                    if isinstance(n, A.Call) and n.method and not n.local:
                        self.program.timer_dbs.setdefault(n.callee.lower(), set()).add(n.method)
        return self.program.timer_dbs.get(name.lower(), set())

    def db_static(self, name: str, db: A.DataBlock | None, node) -> A.VarDecl:
        loc = db.loc if db is not None else node.loc
        d = A.VarDecl(
            loc, name, "", loc, None, A.Section.STATIC, comment=f'the DB "{name}"', db=True
        )
        of = db.of_type if db is not None else "IEC_TIMER"
        if of is not None and of.upper() == "IEC_TIMER":
            d.type_name = self.timer_of(name, node if db is None else db)
        elif of is not None:
            if self.program.blocks.get(of.lower()) is None:
                refuse(
                    Code.DB,
                    db,
                    f'the DB "{name}" is an instance of {of}, which is no FB of the sources',
                )
            d.type_name = of
        else:
            members = {m.name.lower(): m for m in db.decls}
            for value in db.values:  # BEGIN name := value; a member's start value
                m = members.get(value.target.name.lower())
                if m is None or value.target.members:
                    refuse(Code.DB, value, f"the DB \"{name}\" has no member '{value.target.name}'")
                m.init = value.value
            for m in db.decls:
                m.section = A.Section.MEMBER
            d.type_ref = A.StructTypeRef(loc, db.decls)
        self.block.decls.append(d)
        self.declare(d)
        if of is not None and of.upper() != "IEC_TIMER":
            d.db_starts = self.instance_starts(name, d.type, db.values)
        return d

    def instance_starts(self, name: str, fb: T.FbType, values: list) -> list:
        """The start values an instance DB gives its FB's members (BEGIN speed := 3.0;), as TIA
        exports those that differ from the FB's: (the member, its checked start) each, set
        after the FB's own (docs/scl.md §3.9 [S7-DB-START])."""
        starts = []
        for value in values:
            m = fb.block.names.get(value.target.name.lower())
            sections = (A.Section.INPUT, A.Section.OUTPUT)
            if m is None or value.target.members or not (m.section in sections or m.section.static):
                what = f"no input, output or static '{value.target.name}'"
                refuse(Code.DB, value, f'the FB {fb.name} of "{name}" has {what}')
            if not isinstance(m.type, (T.Elementary, T.StringType)):
                refuse(
                    Code.UNSUPPORTED,
                    value,
                    f"the instance DB \"{name}\": a start value of '{m.name}', a "
                    f"{m.type_name}: only of an elementary member",
                )
            what = f"the start value of {name}.{m.name}"
            starts.append((m, self.initial(value.value, m.type, what)))
        return starts

    def timer_of(self, name: str, node) -> str:
        """TON, TOF or TP: the one timer that the program runs on the IEC_TIMER DB `name` (a DB
        without a DATA_BLOCK in the sources is one, if a block runs a timer on it)."""
        used = self.timers_on(name)
        if len(used) != 1 or not used <= set(TIMERS):
            refuse(
                Code.DB,
                node,
                f'the IEC_TIMER DB "{name}" must run one timer, "{name}".TON/TOF/TP(...), '
                f"not {', '.join(sorted(used)) or 'none'}",
            )
        return next(iter(used))

    def user_fb(self, name: str, loc):
        """The instance type of the user FUNCTION_BLOCK name (checked first), or None for no
        block of that name."""
        block = self.program.blocks.get(name.lower())
        if block is None:
            return None
        if block.kind != "FUNCTION_BLOCK":
            refuse(
                Code.INSTANCE,
                A.Node(loc),
                f'{block.name} is a FUNCTION: it has no instance; call it as "{block.name}"(...)',
            )
        return self.program.unit(block.name, A.Node(loc)).instance_type()

    def instance_type(self) -> T.FbType:
        if self.fb_type is None:
            sections = {A.Section.INPUT: {}, A.Section.OUTPUT: {}}
            for d in self.block.decls:
                if d.section in sections:
                    sections[d.section][d.name.upper()] = d.type
            self.fb_type = T.FbType(
                self.block.name,
                "",
                sections[A.Section.INPUT],
                sections[A.Section.OUTPUT],
                timed=True,
                block=self,
            )
        return self.fb_type

    def returns(self):
        """An FC's return value: a variable of the FC's own name (#Fc := ...)."""
        name = self.block.return_type
        if name.upper() == "VOID":
            return
        t = T.lookup(name)
        if t is None and name.lower() in self.program.udts:  # TADDR_Param, a UDT of the program
            t = self.udt(self.program.udts[name.lower()], self.block.loc)
        # a DTL is returned whole, as scl_dtl, a UDT as its C struct, an elementary value as its
        # C type, 64-bit ones too: no FMI variable holds it (docs/scl.md §3.7)
        if not isinstance(t, (T.StringType, T.StructType, T.Elementary)) and t is not T.DTL:
            refuse(
                Code.UNSUPPORTED,
                self.block,
                f"the FUNCTION {self.block.name} : {name}: unsupported return type",
            )
        self.return_type = t
        key = self.block.name.lower()
        if key in self.names:
            refuse(
                Code.RESERVED,
                self.names[key],
                f"'{self.names[key].name}' is the name of its FUNCTION",
            )
        d = A.VarDecl(self.block.loc, self.block.name, name, self.block.loc, None, "RETURN")
        d.type = t
        self.names[key] = d

    def user_unit(self, c: A.Call):
        """The checked FC that c calls, None where no block of the sources has its name."""
        block = self.program.blocks.get(c.callee.lower())
        if block is None:
            return None
        if block.kind == "ORGANIZATION_BLOCK" and not (
            self.program.schedule and self.block is self.program.top
        ):
            refuse(
                Code.STATEMENT,
                c,
                f"{block.name} is an ORGANIZATION_BLOCK: only the CPU calls an OB, on its "
                "event (program.toml, docs/scl.md §3.10)",
            )
        if block.kind == "FUNCTION_BLOCK":
            refuse(
                Code.INSTANCE,
                c,
                f"{block.name} is a FUNCTION_BLOCK: declare an instance of it in VAR "
                f'(#inst : "{block.name}";) and call #inst(...)',
            )
        return self.program.unit(block.name, c)
