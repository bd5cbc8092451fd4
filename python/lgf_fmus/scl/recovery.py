"""A syntax error of an SCL source, and the parser's way on after it (docs/scl.md §5): the error
names what was found and what may stand there, or the construct outside the subset it is
(unsupported.py); the text from the start of the statement or declaration it stands in to its
end (or the one token too many) is skipped, so that the next error is found too."""

from __future__ import annotations

import re

import lark

from . import ast as A
from . import parser, unsupported
from .diagnostics import Code
from .tia import WORDS

# what a terminal of scl.lark is, in an error message
_WORDS = {
    "NAME": "a name",
    "LOCAL_NAME": "#name",
    "QUOTED": '"name"',
    "INT_LIT": "an integer",
    "REAL_LIT": "a real number",
    "BASED_INT": "16#..",
    "TYPED_INT": "a typed literal",
    "TIME_LIT": "T#..",
    "TRUE": "TRUE",
    "FALSE": "FALSE",
    "ADD_OP": "'+'",
    "MINUS": "'-'",
    "MUL_OP": "'*', '/' or MOD",
    "POW_OP": "'**'",
    "EQ_OP": "'=' or '<>'",
    "REL_OP": "a comparison",
    "AND_OP": "AND",
    "OR_OP": "OR",
    "XOR_OP": "XOR",
    "UNARY_OP": "NOT",
    "COMPOUND_OP": "'+=', '-=', '*=' or '/='",
    "VAR_KIND": "VAR_INPUT, VAR_OUTPUT, VAR, ...",
    "REGION_LINE": "REGION",
    "TITLE_LINE": "TITLE",
    "HEADER_LINE": "VERSION, AUTHOR, ...",
    "BIT_ACCESS": "%X<bit>",
    **WORDS,
}


def _describe(expected) -> str:
    terminals = {t.name: t for t in parser._lark().terminals}
    words = []
    for name in expected:
        t = terminals.get(name)
        if name in _WORDS:
            words.append(_WORDS[name])
        elif t is not None and t.pattern.type == "str":
            value = t.pattern.value
            words.append(value.upper() if value.isalpha() or "_" in value else repr(value))
        else:
            words.append(name)
    words = sorted(set(words))
    if len(words) > 10:
        words = words[:10] + ["..."]
    return ", ".join(words)


# where a statement or a declaration starts after these (a syntax error's text is skipped from
# there), and ends at a ";" or before these (docs/scl.md §5: every syntax error reported)
_OPENERS = {
    "BEGIN",
    "THEN",
    "ELSE",
    "DO",
    "REPEAT",
    "STRUCT",
    "VAR_KIND",
    "SEMICOLON",
    "REGION_LINE",
}
_CLOSER = re.compile(r";|\b(?:END_[A-Z_]+|ELSE|ELSIF|UNTIL|BEGIN|VAR_[A-Z_]+|VAR)\b", re.IGNORECASE)


def _tokens_before(text: str) -> list:
    """The tokens the parser took before the syntax error of text (the last one being the
    unexpected token, if a token was)."""
    parser._line_comments.found = []
    seen = []
    try:
        for token in parser._lark().parse_interactive(text).iter_parse():
            seen.append(token)
    except lark.exceptions.UnexpectedInput:
        pass
    return seen


def syntax_error(e, text: str, file: str):
    """(the SclError of Lark's error e in text, (start, end) of the text to skip to go on, or
    None where nothing is left to go on with)."""
    if isinstance(e, lark.exceptions.UnexpectedCharacters):
        at, token = e.pos_in_stream, None
        char = text[at]
        message = unsupported.CHARACTERS.get(char)
        code = Code.UNSUPPORTED if message else Code.SYNTAX
        message = message or f"unexpected character {char!r}"
        loc = A.Loc(file, e.line, e.column)
    elif isinstance(e, lark.exceptions.UnexpectedToken) and e.token.type != "$END":
        token, at = e.token, e.token.start_pos
        loc = A.Loc(file, e.line, e.column)
        code, message = Code.SYNTAX, f"unexpected {str(token)!r}; expected {_describe(e.expected)}"
    else:  # the end of the file
        lines = text.count("\n") + 1
        expected = e.expected if isinstance(e, lark.exceptions.UnexpectedEOF) else e.expected
        error = A.SclError(
            A.Loc(file, lines, 1),
            f"unexpected end of file; expected {_describe(set(expected))}",
            Code.SYNTAX,
        )
        return error, None
    seen = _tokens_before(text)
    if seen and token is not None and seen[-1].start_pos == at:
        seen = seen[:-1]  # the unexpected token itself
    if token is not None:
        message = _not_scl(token, seen, e.expected) or message
    # a construct outside the subset, named: the word at the error or the one before it
    for candidate in [token, seen[-1] if seen else None]:
        if candidate is not None and unsupported.word_message(str(candidate)):
            code, message = Code.UNSUPPORTED, unsupported.word_message(str(candidate))
            loc = A.Loc(file, candidate.line, candidate.column)
            break
    error = A.SclError(loc, message, code)
    start = 0
    for t in reversed(seen):
        if t.type in _OPENERS or str(t).upper() in _OPENERS:
            start = t.end_pos
            break
    closer = _CLOSER.search(text, at + 1 if token is None else at)
    if closer is None:
        return error, None
    end = closer.end() if closer.group(0) == ";" else closer.start()
    # a token too many (THEN THEN): without it the parse goes on past the next statement
    if token is not None:
        after = text.find(";", max(end, token.end_pos))
        later = _error_at(blank(text, at, token.end_pos))
        if later is None or later > (after if after >= 0 else len(text)):
            return error, (at, token.end_pos)
    if end <= start or not text[start:end].strip():
        return error, None
    return error, (start, end)


NOT_SCL = "the source is not valid SCL (docs/scl.md §6)"


def _not_scl(token, seen: list, expected) -> str | None:
    """The message of a syntax error that is a mistake of the source, not a construct of S7
    outside the subset: a comparison written as a statement, a member written with #, an END_
    of nothing, text before the first block (docs/scl.md §6: source that is not valid SCL)."""
    text, words = str(token), _describe(expected)
    if text == "=" and "':='" in words:
        return f"'=' compares and assigns nothing, an assignment is ':=': {NOT_SCL}"
    if token.type == "LOCAL_NAME" and seen and str(seen[-1]) == ".":
        return f"a member is named without #, .{text[1:]} and not .{text}: {NOT_SCL}"
    if text.upper().startswith("END_") and "END_" in words:
        return f"{text} without its {text[4:].upper()}: {NOT_SCL}"
    if not seen and "FUNCTION_BLOCK" in words:
        return f"{text!r} before the first block (an SCL source holds blocks only): {NOT_SCL}"
    return None


def _error_at(text: str) -> int | None:
    """Where the first syntax error of text is, None if it has none."""
    try:
        parser._lark().parse(text)
        return None
    except lark.exceptions.UnexpectedCharacters as e:
        return e.pos_in_stream
    except lark.exceptions.UnexpectedToken as e:
        return e.token.start_pos if e.token.type != "$END" else len(text)
    except lark.exceptions.UnexpectedEOF:
        return len(text)


def blank(text: str, start: int, end: int) -> str:
    """text with [start, end) as spaces, its line breaks kept (so the places after it stay)."""
    return text[:start] + re.sub(r"[^\n]", " ", text[start:end]) + text[end:]
