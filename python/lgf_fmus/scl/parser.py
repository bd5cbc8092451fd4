"""The front end: SCL text -> syntax tree (ast.py), with Lark's LALR(1) parser on scl.lark
(docs/scl.md §2). A syntax error becomes an SclError at its file:line:col, naming what was
found and what may stand there."""

from __future__ import annotations

import re
import threading
from functools import lru_cache
from pathlib import Path

import lark
from lark import Lark, Transformer, v_args

from . import ast as A
from . import recovery
from .diagnostics import LIMIT, Code
from .literals import integer as _int
from .literals import time_ms, time_ns
from .tia import TiaSyntax, constants_in_place, time_ranges

GRAMMAR = Path(__file__).with_name("scl.lark")

# the // comments the lexer meets while one parse runs (a declaration's is its description)
_line_comments = threading.local()


def _line_comment(token):
    _line_comments.found.append(token)
    return token


@lru_cache(maxsize=1)
def _lark() -> Lark:
    return Lark(
        GRAMMAR.read_text(encoding="utf-8"),
        parser="lalr",
        lexer="contextual",
        propagate_positions=True,
        maybe_placeholders=True,
        lexer_callbacks={"LINE_COMMENT": _line_comment},
        # the parse tables, kept by Lark in the temporary folder keyed by the grammar's hash:
        # building them takes longer than compiling a block's SCL
        cache=True,
    )


def tokens(text: str) -> list[lark.Token]:
    """The tokens of an SCL text as the parser reads them (the contextual lexer, comments and
    pragmas left out), up to the first syntax error."""
    _line_comments.found = []
    return _lark().parse_interactive(text).exhaust_lexer()


# the attribute pragma after a declared name, { Name := 'Value'; ... }, and each of its pairs
ATTRIBUTES = re.compile(r"\s*\{([^}]*)\}")
ATTRIBUTE = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)\s*:=\s*'([^']*)'")


def _name(text: str) -> str:
    """A name as SCL writes it (#name, "name" or name) without its marks."""
    text = text[1:] if text.startswith("#") else text
    return text[1:-1] if text.startswith('"') else text


class _Builder(TiaSyntax, Transformer):  # TiaSyntax: what TIA writes (docs/scl.md §2.1)
    def __init__(self, file: str, comments: dict[int, str], text: str):
        super().__init__()
        self.file = file
        self.comments = comments
        self.errors = []  # the Diagnostics of literals of a wrong form
        self.text, self.starts = text, {}  # the source; id of a Literal -> its offset there
        self.attributes = {}  # (line, column) of a declared name -> its attributes

    def _loc(self, meta_or_token) -> A.Loc:
        return A.Loc(self.file, meta_or_token.line, meta_or_token.column)

    # Blocks and declarations

    def start(self, units):
        return list(units)

    @v_args(meta=True)
    def function_block(self, meta, children):
        name, *rest = children
        headers = dict(h for h in rest if isinstance(h, tuple))
        sections = [
            c for c in rest if isinstance(c, list) and (not c or isinstance(c[0], A.VarDecl))
        ]
        body = rest[-1]
        decls = [d for s in sections for d in s]
        constants_in_place(decls, body, self.errors)
        return A.Block(
            self._loc(meta),
            "FUNCTION_BLOCK",
            name,
            headers,
            decls,
            body,
            comment=headers.get("TITLE", ""),
        )

    @v_args(meta=True)
    def function(self, meta, children):
        name, return_type, *rest = children
        block = self.function_block(meta, [name, *rest])
        # an ARRAY or STRUCT return type keeps its word, for checks.py to refuse by name
        if isinstance(return_type, tuple):
            return_type = return_type[0]
        else:
            return_type = "ARRAY" if isinstance(return_type, A.ArrayTypeRef) else "STRUCT"
        block.kind, block.return_type = "FUNCTION", return_type
        return block

    @v_args(meta=True)
    def organization_block(self, meta, children):
        """An OB (docs/scl.md §3.10): to the checks an FC : Void that only the program's schedule
        calls."""
        block = self.function_block(meta, children)
        block.kind, block.return_type = "ORGANIZATION_BLOCK", "Void"
        return block

    @v_args(meta=True)
    def data_block(self, meta, children):
        name, *rest = children
        headers = dict(h for h in rest if isinstance(h, tuple))
        of_type = headers.pop(" of", None)
        sections = [c for c in rest if isinstance(c, list) and c and isinstance(c[0], A.VarDecl)]
        values = [c for c in rest if isinstance(c, A.Assign)]
        decls = [d for section in sections for d in section]
        constants_in_place(decls, [], self.errors)
        return A.DataBlock(self._loc(meta), name, headers, of_type, decls, values)

    def db_type(self, children):
        return " of", _name(str(children[0]))  # beside the headers, under a key none has

    @v_args(meta=True)
    def db_value(self, meta, children):
        return A.Assign(self._loc(meta), children[0], children[1])

    @v_args(meta=True)
    def type_decl(self, meta, children):
        name, *rest = children
        headers = dict(h for h in rest if isinstance(h, tuple))
        constants_in_place([rest[-1]], [], self.errors)
        return A.TypeDecl(self._loc(meta), name, headers, rest[-1])

    @v_args(meta=True)
    def array_type(self, meta, children):
        *dims, element = children
        return A.ArrayTypeRef(self._loc(meta), dims, element)

    def dim_range(self, children):
        return (children[0], children[1])

    def dim_any(self, _):
        return None

    @v_args(meta=True)
    def struct_type(self, meta, children):
        members = [d for group in children for d in group]
        for d in members:
            d.section = A.Section.MEMBER
        return A.StructTypeRef(self._loc(meta), members)

    @v_args(meta=True)
    def array_init(self, meta, children):
        return A.ArrayInit(self._loc(meta), list(children))

    def init_one(self, children):
        return (1, children[0])

    def init_repeat(self, children):
        return (_int(str(children[0])), children[1])

    @v_args(meta=True)
    def struct_init(self, meta, children):
        return A.StructInit(self._loc(meta), list(children))

    def member_init(self, children):
        name, value = children
        return (_name(str(name)), self._loc(name), value)

    def block_name(self, children):
        return _name(str(children[0]))

    def header(self, children):
        text = str(children[0])
        key, value = re.split(r"\s*[=:]\s*", text, maxsplit=1)
        return (key.upper(), value.strip())

    def var_section(self, children):
        kind = A.Section(" ".join(str(children[0]).upper().split()))
        decls = []
        for group in children[1:]:
            for d in group:
                d.section = kind
                decls.append(d)
        return decls

    @v_args(meta=True)
    def var_decl(self, meta, children):
        *names, type_ref, init = children
        if isinstance(type_ref, tuple):
            (type_name, type_loc), ref = type_ref, None
        else:  # ARRAY or STRUCT: each declared name gets the type (docs/scl.md §3.1)
            type_name = (
                type_ref.name
                if isinstance(type_ref, A.SizedTypeRef)
                else "ARRAY"
                if isinstance(type_ref, A.ArrayTypeRef)
                else "STRUCT"
            )
            type_loc, ref = type_ref.loc, type_ref
        return [
            A.VarDecl(
                loc,
                name,
                type_name,
                type_loc,
                init,
                "",
                comment=self.comments.get(loc.line, ""),
                type_ref=ref,
                attributes=self.attributes.get((loc.line, loc.column), {}),
            )
            for name, loc in names
        ]

    def decl_name(self, children):
        token = children[0]
        loc = self._loc(token)
        # a member's attributes, the pragma between its name and ":" as TIA writes them:
        # level { S7_SetPoint := 'True'} : Real (docs/scl.md §3.9 [S7-DB-SETPOINT])
        pragma = ATTRIBUTES.match(self.text, token.end_pos)
        if pragma:
            pairs = ATTRIBUTE.findall(pragma.group(1))
            self.attributes[(loc.line, loc.column)] = {k.lower(): v for k, v in pairs}
        return _name(str(token)), loc

    def type_name(self, children):
        token = children[0]
        return _name(str(token)), self._loc(token)

    def sized_type_name(self, children):
        """STRING[20], STRING[#LEN]: the type with its length, for the checks (docs/scl.md
        §3.1); a global constant's name is kept quoted, for the checks to refuse."""
        name, size = children
        text = str(size)
        value = _int(text) if size.type == "INT_LIT" else text
        return A.SizedTypeRef(self._loc(name), _name(str(name)), value)

    # Statements

    def statements(self, children):
        flat = []
        for c in children:  # a chained assignment is a list of assignments
            flat.extend(c if isinstance(c, list) else [] if c is None else [c])
        return flat

    def empty_statement(self, _):
        return None

    @v_args(meta=True)
    def region(self, meta, children):
        title, body, _end = children  # the text after END_REGION is a comment (§2.1)
        return A.Region(self._loc(meta), str(title)[6:].strip(), body)

    @v_args(meta=True)
    def assign(self, meta, children):
        target, value = children
        return A.Assign(self._loc(meta), target, value)

    @v_args(meta=True)
    def chained_assign(self, meta, children):
        """#a := #b := e (S7's chained assignment): e into #b, then #b into #a, in order."""
        target, inner = children
        inner = inner if isinstance(inner, list) else [inner]
        last = inner[-1].target
        value = A.VarRef(last.loc, last.name, list(last.members), last.local)
        value.quoted = last.quoted
        return [*inner, A.Assign(self._loc(meta), target, value)]

    @v_args(meta=True)
    def compound_assign(self, meta, children):
        target, op, value = children
        return A.Assign(self._loc(meta), target, value, op=str(op))

    @v_args(meta=True)
    def call_statement(self, meta, children):
        return A.CallStmt(self._loc(meta), children[0])

    @v_args(meta=True)
    def if_statement(self, meta, children):
        condition, body, *rest = children
        branches = [(condition, body)]
        otherwise = None
        for part in rest:
            if part is None:
                continue
            if part[0] == "elsif":
                branches.append(part[1:])
            else:
                otherwise = part[1]
        return A.If(self._loc(meta), branches, otherwise)

    def elsif(self, children):
        return ("elsif", children[0], children[1])

    def else_part(self, children):
        return ("else", children[0])

    @v_args(meta=True)
    def case_statement(self, meta, children):
        selector, *rest = children
        otherwise = None
        if rest and (rest[-1] is None or rest[-1][0] == "else"):
            last = rest.pop()
            otherwise = last[1] if last else None
        return A.Case(
            self._loc(meta), selector, [(labels, body) for labels, body in rest], otherwise
        )

    def case_branch(self, children):
        *labels, body = children
        return (labels, body)

    def case_value(self, children):
        return (children[0], children[0])

    def case_range(self, children):
        return (children[0], children[1])

    def signed_int(self, children):
        sign, token = children
        text = str(token)
        if re.match(r"[A-Za-z]", text):  # INT#5, WORD#16#FF: the value after the type
            text = text.split("#", 1)[1]
        value = _int(text)
        return -value if sign else value

    @v_args(meta=True)
    def for_statement(self, meta, children):
        variable, start, end, step, body = children
        return A.For(self._loc(meta), variable, start, end, step, body)

    @v_args(meta=True)
    def while_statement(self, meta, children):
        return A.While(self._loc(meta), children[0], children[1])

    @v_args(meta=True)
    def repeat_statement(self, meta, children):
        return A.Repeat(self._loc(meta), children[0], children[1])

    @v_args(meta=True)
    def exit_statement(self, meta, _):
        return A.Jump(self._loc(meta), "EXIT")

    @v_args(meta=True)
    def continue_statement(self, meta, _):
        return A.Jump(self._loc(meta), "CONTINUE")

    @v_args(meta=True)
    def return_statement(self, meta, _):
        return A.Jump(self._loc(meta), "RETURN")

    @v_args(meta=True)
    def goto_statement(self, meta, children):
        return A.Goto(self._loc(meta), str(children[0]))

    @v_args(meta=True)
    def jump_label(self, meta, children):
        return A.Label(self._loc(meta), str(children[0]))

    # Expressions

    @v_args(meta=True)
    def binary(self, meta, children):
        left, op, right = children
        return A.Binary(self._loc(meta), str(op).upper(), left, right)

    @v_args(meta=True)
    def unary_op(self, meta, children):
        op, operand = children
        if (literal := self.signed(op, operand)) is not None:  # -32768 (docs/scl.md §2.1)
            return literal
        return A.Unary(self._loc(meta), str(op).upper(), operand)

    @v_args(meta=True)
    def call(self, meta, children):
        (callee, local, quoted, method, *index), *args = children
        call = A.Call(self._loc(meta), callee, local, [a for a in args if a is not None])
        call.quoted, call.method = quoted, method
        call.index = index[0] if index else None
        return call

    def callee_name(self, children):
        text = str(children[0])
        return _name(text), text.startswith("#"), text.startswith('"'), None

    def callee_method(self, children):
        return _name(str(children[0])), False, True, str(children[1]).upper()

    def callee_local_method(self, children):  # #inst.TON(...) of an IEC_TIMER static
        return _name(str(children[0])), True, False, str(children[1]).upper()

    @v_args(meta=True)
    def callee_element(self, meta, children):  # #axes[#i](...): an element of an ARRAY of instances
        name, *exprs = children
        return _name(str(name)), True, False, None, A.Index(self._loc(meta), exprs)

    @v_args(meta=True)
    def positional(self, meta, children):
        return A.Argument(self._loc(meta), None, children[0])

    @v_args(meta=True)
    def named_in(self, meta, children):
        return A.Argument(self._loc(meta), _name(str(children[0])), children[1])

    @v_args(meta=True)
    def named_out(self, meta, children):
        return A.Argument(self._loc(meta), _name(str(children[0])), None, children[1])

    @v_args(meta=True)
    def variable(self, meta, children):
        head, *members = children
        text = str(head)
        ref = A.VarRef(self._loc(meta), _name(text), list(members), text.startswith("#"))
        ref.quoted = text.startswith(('"', "%"))  # an address: a tag's (docs/scl.md §3.11)
        if text.startswith("%"):
            ref.name = text.upper()
        return ref

    def member(self, children):
        return _name(str(children[0]))  # .x or ."x" (docs/scl.md §2.1)

    @v_args(meta=True)
    def index(self, meta, children):
        return A.Index(self._loc(meta), list(children))

    @v_args(meta=True)
    def bit(self, meta, children):
        return A.Bit(self._loc(meta), int(str(children[0])[2:]))

    def _literal(self, kind, token, value, prefix=None):
        literal = A.Literal(self._loc(token), kind, str(token), value, prefix)
        self.starts[id(literal)] = token.start_pos
        return literal

    def int_literal(self, children):
        return self._literal("int", children[0], _int(str(children[0])))

    def based_literal(self, children):
        text = str(children[0])
        parts = text.split("#")
        prefix = self.bit_string_prefix(parts[0].upper() if len(parts) == 3 else None)
        return self._literal("int", children[0], _int(text), prefix)

    def typed_literal(self, children):
        text = str(children[0])
        prefix, digits = text.split("#", 1)
        digits = digits.replace("_", "")
        if prefix.upper() == "C":  # C#500 (docs/scl.md §2.1)
            return self.count_literal(children[0])
        if re.fullmatch(r"[+-]?[0-9]+", digits):
            return self._literal("int", children[0], int(digits), prefix.upper())
        return self._literal("real", children[0], float(digits), prefix.upper())

    def real_literal(self, children):
        return self._literal("real", children[0], float(str(children[0]).replace("_", "")))

    def time_literal(self, children):
        token = children[0]
        if str(token).upper().startswith("L"):
            ns = time_ns(str(token))
            if ns is None:
                self._error(token, f"{token}: not an LTIME literal (LT#1s5ns)")
            return self._literal("time", token, ns or 0, "LTIME")
        ms = time_ms(str(token))
        if ms is None:
            self._error(token, f"{token}: not a TIME literal (T#1s200ms)")
        return self._literal("time", token, ms or 0, "TIME")

    def _error(self, token, message: str, code=Code.LITERAL):
        self.errors += A.SclError(self._loc(token), message, code).diagnostics

    def bool_literal(self, children):
        return self._literal("bool", children[0], str(children[0]).upper() == "TRUE", "BOOL")


def parse(text: str, file: str) -> list[A.Block]:
    """The blocks of one SCL source. Raises an SclError of every syntax error (up to the
    diagnostics' limit): after an error the parser skips to the end of its statement or
    declaration and goes on."""
    errors, current, tree = [], text, None
    for _ in range(LIMIT):
        _line_comments.found = []
        try:
            tree = _lark().parse(current)
            break
        except lark.exceptions.UnexpectedInput as e:
            error, skip = recovery.syntax_error(e, current, file)
            if errors and error.loc == errors[-1].loc:
                break  # skipping did not move the error: the rest would repeat it
            errors.append(error.diagnostics[0])
            if skip is None:
                break
            current = recovery.blank(current, *skip)
    if errors:
        raise A.SclError.of(errors, {file: text})
    # the line comments, for the descriptions of the declarations they follow
    comments = {t.line: str(t)[2:].strip() for t in _line_comments.found}
    builder = _Builder(file, comments, text)
    blocks = builder.transform(tree)
    time_ranges(blocks, builder.errors)
    if builder.errors:
        raise A.SclError.of(builder.errors, {file: text})
    return blocks
