"""The lexer (docs/scl.md §2, §3.4): comments stand between any two tokens and change nothing
(// after an operand is a comment, not a division), `*=` and `/=` are one token each. The
constructs' values are in test_constructs.py (test_compound_assignment,
test_comments_stand_between_any_two_tokens); here every twin is compiled to C again with a
comment after each of its tokens, and must give the same C."""

from __future__ import annotations

import re

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import parser
from tests.scl.driver import TWINS

# tokens that run to the end of their line: a comment after one is part of its text
LINE_TOKENS = {"TITLE_LINE", "HEADER_LINE", "REGION_LINE"}


def commented(text: str, comment: str, body_only=False) -> str:
    """text with `comment` after each token (not after the line tokens)."""
    out, at = [], 0
    body = not body_only
    for token in parser.tokens(text):
        end = token.end_pos
        out.append(text[at:end])
        at = end
        if str(token).upper() == "BEGIN":
            body = True
        if token.type not in LINE_TOKENS and body:
            out.append(comment)
    return "".join(out) + text[at:]


def without_comments(c: str) -> str:
    """The C without its comments, the places of its loops (file:line, which the cycle watchdog
    names, docs/scl.md §3.4) and the FMU's GUID (a hash of the source text)."""
    c = re.sub(r"/\*.*?\*/", "", c, flags=re.S)
    c = re.sub(r'scl_time_error\(ctx, "[^"]*"\)', "scl_time_error(ctx, place)", c)
    c = re.sub(r"\{[0-9a-f]{8}(-[0-9a-f]{4}){3}-[0-9a-f]{12}\}", "{guid}", c)
    return " ".join(c.split())  # clang-format lays the C out after the comments' lengths


def c_of(tmp_path, name: str, text: str, block: str) -> dict:
    source = tmp_path / name
    source.write_text(text, encoding="utf-8")
    return {k: without_comments(v) for k, v in scl.generate_c([source], block).items()}


@pytest.mark.parametrize("twin", sorted(p.stem for p in TWINS.glob("*.scl")))
@pytest.mark.parametrize(
    "comment, body_only",
    [(" (* c *) ", False), (" /* c */ ", False), ("(*(*)", False), (" // c\n", True)],
    ids=["paren-star", "slash-star", "tight", "line"],
)
def test_a_comment_after_every_token_changes_no_c(tmp_path, twin, comment, body_only):
    text = (TWINS / f"{twin}.scl").read_text(encoding="utf-8")
    plain = c_of(tmp_path, "plain.scl", text, twin)
    noisy = commented(text, comment, body_only)
    assert noisy.count(comment.strip()) > 50
    assert c_of(tmp_path, "noisy.scl", noisy, twin) == plain


@pytest.mark.parametrize(
    "text, expected",
    [
        ("#y *= 2;", ["#y", "*=", "2", ";"]),
        ("#y /= #x;", ["#y", "/=", "#x", ";"]),
        ("#y := #x // 1\n/ 2;", ["#y", ":=", "#x", "/", "2", ";"]),
        ("#y := #x/(*c*)2;", ["#y", ":=", "#x", "/", "2", ";"]),
        ("#y := #x/*c*//2;", ["#y", ":=", "#x", "/", "2", ";"]),
        ("#y := #x**2*3;", ["#y", ":=", "#x", "**", "2", "*", "3", ";"]),
        ("#y:=(*(*)#x(**)*(2);", ["#y", ":=", "#x", "*", "(", "2", ")", ";"]),
    ],
)
def test_operators_and_comments_are_lexed_apart(text, expected):
    head = 'FUNCTION_BLOCK "F"\nBEGIN\n'
    assert [str(t) for t in parser.tokens(head + text)][3:] == expected
