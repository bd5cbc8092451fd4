"""The C of SCL's names and data (docs/scl.md §4), shared by the C generation's files: the C name
of each SCL name, the C declaration of each type, the C prefix and struct of each block, and
the scalars an ARRAY or STRUCT holds with their C paths and FMI names."""

from __future__ import annotations

import re

from . import ast as A
from . import types as T
from .types import K

C_KEYWORDS = set(
    "auto break case char const continue default do double else enum extern float for goto if "
    "inline int long register restrict return short signed sizeof static struct switch typedef "
    "union unsigned void volatile while block call data".split()
)
# what the generated C's headers define (stdbool, stdint, stddef, math, stdio, string) or the
# generated code names itself: an SCL name that is one of them gets a "_" in the C
C_NAMES = set(
    "bool true false NULL INFINITY NAN HUGE_VAL EOF errno assert offsetof stdin stdout stderr "
    "b f ctx plc model variables statics lgf_model init check status status_text".split()
)
C_MACRO = re.compile(r"U?INT(8|16|32|64|MAX|PTR)_(MIN|MAX|C)|SIZE_MAX|(FLT|DBL|LDBL)_\w+|E[A-Z]+")
C_PREFIXES = ("scl_", "iec_", "lgf_", "core_", "fmi", "var_", "role_", "field_")
# a name C and FMI's structured naming convention (FMI 2.0 §2.2.9, FMI 3.0 §2.4.7.5.1) take as
# it is; any other (a quoted name of TIA, docs/scl.md §2) is mangled in the C, quoted in FMI
PLAIN_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
_KEPT = re.compile(r"[A-Za-z0-9_]")


def identifier(name: str) -> str:
    """An SCL name as a C identifier (docs/scl.md §3.11 [DEC-NAME-C]): a name of letters, digits
    and _ as it is; any other as q_ and its characters, each one but ASCII letters, digits and _
    as _<its code in hex>_ ("Conveyor.Main" is q_Conveyor_2e_Main, "Größe" q_Gr_f6__df_e).
    Two names may still come out alike ("a.b" and q_a_2e_b): the checks refuse that."""
    if PLAIN_NAME.match(name):
        return name
    return "q_" + "".join(c if _KEPT.match(c) else f"_{ord(c):x}_" for c in name)


def fmi_part(name: str) -> str:
    """An SCL name as a part of an FMI variable name (docs/scl.md §3.11 [DEC-NAME-FMI]): a name
    of letters, digits and _ as it is, any other as FMI's quoted name ('Conveyor.Main', a ' or
    \\ escaped by \\), so that no quoted name reads as a path of members or an index."""
    if PLAIN_NAME.match(name):
        return name
    return "'" + name.replace("\\", "\\\\").replace("'", "\\'") + "'"


def field(name: str) -> str:
    """The C name of an SCL name: its own (mangled where it is no C identifier), unless C or
    the generated code has it already."""
    name = identifier(name)
    clash = (
        name in C_KEYWORDS
        or name in C_NAMES
        or C_MACRO.fullmatch(name)
        or name.lower().startswith(C_PREFIXES)
    )
    return name + "_" if clash else name


def is_table(d) -> bool:
    """An ARRAY[*] VAR_IN_OUT: a table of tunable parameters with its size (docs/scl.md §4)."""
    return isinstance(d.type, T.ArrayType) and d.type.dims is None


def is_open(t) -> bool:
    """ARRAY[*] (of any number of dimensions)."""
    return isinstance(t, T.ArrayType) and t.dims is None


def by_reference(d, checker) -> bool:
    """A parameter that the call passes by reference, as S7 does (docs/scl.md §3.7): an in/out
    of an FC or of an FB the FMU's FB uses, an FC's input or output of a STRUCT, UDT or ARRAY
    (ARRAY[*] included). (The FMU's FB holds its own in/outs: they are FMI variables, §4.)"""
    if checker.block is checker.program.top:
        return False
    if d.section == A.Section.IN_OUT:
        return True
    structured = isinstance(d.type, (T.ArrayType, T.StructType))
    return d.section.interface and (is_open(d.type) or checker.fc and structured)


def bound_fields(name: str, rank: int) -> list[tuple[str, str]]:
    """The C fields of the low and high bound of each dimension of the ARRAY[*] name passed by
    reference (no SCL name starts with scl_)."""
    return [(f"scl_lo{k}_{name}", f"scl_hi{k}_{name}") for k in range(1, rank + 1)]


def reference_decls(name: str, t) -> list[str]:
    """The C declarations of a parameter passed by reference: a pointer to the variable; of an
    ARRAY[*], a pointer to its first element and its bounds."""
    if is_open(t):
        bounds = [f"int32_t {b}" for pair in bound_fields(name, t.rank) for b in pair]
        return [c_decl("*" + name, t.element), *bounds]
    return [c_decl(f"(*{name})" if isinstance(t, T.ArrayType) else f"*{name}", t)]


def c_decl(name: str, t) -> str:
    """The C declaration of a field or local name of type t: ARRAY[1..3, 0..1] OF INT is
    int16_t name[3][2], an ARRAY[*] its table of T.TABLE_CAPACITY elements."""
    if isinstance(t, T.ArrayType):
        sizes = (T.TABLE_CAPACITY,) if t.dims is None else t.sizes
        return c_decl(name, t.element) + "".join(f"[{n}]" for n in sizes)
    if isinstance(t, T.FbType) and t.block is not None:  # a user FB's instance
        return f"{struct_of(t.block)} {name}"
    return f"{t.c} {name}"


def zero(t) -> str:
    """0 of t (FALSE, 0, 0.0) as C, in an expression of t."""
    return "false" if t.kind == K.BOOL else "0"


def element_indices(sizes):
    """The C subscripts of every element of an array of these sizes, in S7's order (the last
    index runs fastest)."""
    if not sizes:
        return [""]
    return [f"[{i}]{rest}" for i in range(sizes[0]) for rest in element_indices(sizes[1:])]


def scl_indices(t: T.ArrayType):
    """The SCL indices of every element, as the FMI names write them: [1], [1,0], ..."""
    dims = ((0, T.TABLE_CAPACITY - 1),) if t.dims is None else t.dims

    def walk(k):
        if k == len(dims):
            return [()]
        lo, hi = dims[k]
        return [(i, *rest) for i in range(lo, hi + 1) for rest in walk(k + 1)]

    return ["[" + ",".join(map(str, ix)) + "]" for ix in walk(0)]


def scalars(path: str, name: str, t):
    """(C path, FMI name, elementary type) of every scalar an ARRAY or STRUCT holds."""
    if isinstance(t, T.ArrayType):
        sizes = (T.TABLE_CAPACITY,) if t.dims is None else t.sizes
        return [
            leaf
            for sub, ix in zip(element_indices(sizes), scl_indices(t))
            for leaf in scalars(path + sub, name + ix, t.element)
        ]
    if isinstance(t, T.StructType):
        return [
            leaf
            for key, (m, _) in t.members.items()
            for leaf in scalars(f"{path}.{field(key)}", f"{name}.{fmi_part(key)}", m)
        ]
    return [(path, name, t)]


def described(path: str, name: str, t, comment: str):
    """(C path, FMI name, elementary type, description) of every scalar an ARRAY or STRUCT
    holds: a member's description its comment in the STRUCT or UDT, else the comment of what
    holds it (the declaration's, comment), else none ("")."""
    if isinstance(t, T.ArrayType):
        sizes = (T.TABLE_CAPACITY,) if t.dims is None else t.sizes
        return [
            leaf
            for sub, ix in zip(element_indices(sizes), scl_indices(t))
            for leaf in described(path + sub, name + ix, t.element, comment)
        ]
    if isinstance(t, T.StructType):
        return [
            leaf
            for key, (m, _) in t.members.items()
            for leaf in described(
                f"{path}.{field(key)}",
                f"{name}.{fmi_part(key)}",
                m,
                t.comments.get(key) or comment,
            )
        ]
    return [(path, name, t, comment)]


def overlay(default, given):
    """An initial value given over a member's default: a STRUCT's members and an ARRAY's
    elements that the given value leaves out keep the default's (docs/scl.md §3.8)."""
    if given is None:
        return default
    if isinstance(default, dict) and isinstance(given, dict):
        return {**default, **{k: overlay(default.get(k), v) for k, v in given.items()}}
    if isinstance(default, list) and isinstance(given, list):
        merged = [overlay(d, g) for d, g in zip(default, given)]
        return merged + given[len(default) :] + default[len(given) :]
    return given


def prefix_of(checker) -> str:
    """The C prefix of a block's functions and types: scl_<fb> for an FB, scl_FC_<fc> for an FC
    or OB (upper case, so that no FB's lower-case prefix meets it)."""
    return block_prefix(checker.block)


def block_prefix(block) -> str:
    name = identifier(block.name).lower()
    fc = block.kind in ("FUNCTION", "ORGANIZATION_BLOCK")
    return f"scl_FC_{name}" if fc else f"scl_{name}"


def struct_of(checker) -> str:
    return prefix_of(checker) + ("_frame" if checker.fc else "_block")
