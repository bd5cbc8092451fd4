"""Every rule and terminal of scl.lark is used by a test program (as blark's
test_uncovered_grammar): the twins and the SCL of the tests (their programs, and the sources of
the refusals of test_errors.py) are parsed with every token kept, and a rule or terminal that
none of them reaches fails here: a construct the grammar takes that no test shows."""

from __future__ import annotations

import importlib
from pathlib import Path

import lark
import pytest

from lgf_fmus.scl import parser
from tests.scl.driver import TWINS

# the generated helper rules of Lark (name starting with _) and a rule that only passes its one
# child through (?rule without an alias) leave no node of their own
IGNORED = ("LINE_COMMENT", "BLOCK_COMMENT", "C_COMMENT", "PRAGMA", "WS")
# every test module of the compiler, for the SCL texts it holds
MODULES = sorted(
    p.stem for p in Path(__file__).parent.glob("test_*.py") if p.stem != "test_grammar"
)


def strings(value) -> list[str]:
    """Every string in a value: a str, or one in a list, tuple or dict of them."""
    if isinstance(value, str):
        return [value]
    if isinstance(value, dict):
        value = list(value.values())
    if isinstance(value, (list, tuple)):
        return [s for item in value for s in strings(item)]
    return []


def corpus() -> list[str]:
    """The SCL of the tests: the twins, the programs and fragments the test modules hold (as
    constants and as parameters of their tests), and the sources of test_errors.py's
    refusals."""
    texts = [p.read_text(encoding="utf-8") for p in sorted(TWINS.glob("*.scl"))]
    for name in MODULES:
        module = importlib.import_module(f"tests.scl.{name}")
        for value in vars(module).values():
            texts += strings(value)
            for mark in getattr(value, "pytestmark", []):
                if mark.name == "parametrize":
                    texts += strings(list(mark.args[1]))
    errors = importlib.import_module("tests.scl.test_errors")
    for table in (errors.CASES, errors.CALL_CASES, errors.DB_CASES, errors.MEET_CASES):
        for declarations, body, *rest in table.values():
            after = rest[0] if len(rest) == 2 else ""
            texts.append(errors.fb(declarations, body) + after)
    return texts


# a fragment of a test (a statement, a declaration, an expression) in a program of its own
FRAGMENTS = (
    "{}",
    'FUNCTION_BLOCK "G"\nBEGIN\n{}\nEND_FUNCTION_BLOCK\n',
    'FUNCTION_BLOCK "G"\nVAR\n{}\nEND_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n',
    'FUNCTION_BLOCK "G"\n{}\nBEGIN\nEND_FUNCTION_BLOCK\n',
    'FUNCTION_BLOCK "G"\nBEGIN\n#x := {};\nEND_FUNCTION_BLOCK\n',
)


@pytest.fixture(scope="module")
def used():
    """(rule names, terminal names) the corpus's parse trees hold."""
    rules, terminals = set(), set()

    def seen(name):
        def callback(token):
            terminals.add(name)
            return token

        return callback

    grammar = lark.Lark(
        parser.GRAMMAR.read_text(encoding="utf-8"),
        parser="lalr",
        lexer="contextual",
        keep_all_tokens=True,
        maybe_placeholders=True,
        lexer_callbacks={name: seen(name) for name in IGNORED},
    )
    parsed = 0
    for text in corpus():
        for form in FRAGMENTS:
            try:
                tree = grammar.parse(form.format(text))
                break
            except lark.exceptions.LarkError:
                tree = None  # no SCL, or a test of a syntax error
        if tree is None:
            continue
        parsed += 1
        for node in tree.iter_subtrees():
            rules.add(str(node.data))
            terminals.update(c.type for c in node.children if isinstance(c, lark.Token))
    assert parsed > 100
    return grammar, rules, terminals


def test_every_rule_of_the_grammar_is_used(used):
    grammar, rules, _ = used
    expected = {
        r.alias or r.origin.name
        for r in grammar.rules
        if not (r.alias or r.origin.name).startswith("_")
        and not (r.options.expand1 and not r.alias and len(r.expansion) == 1)
    }
    assert sorted(set(map(str, expected)) - rules) == []


def test_every_terminal_of_the_grammar_is_used(used):
    grammar, _, terminals = used
    assert sorted({t.name for t in grammar.terminals} - terminals) == []


def test_the_corpus_reaches_the_tests_programs():
    texts = corpus()
    assert any('FUNCTION_BLOCK "LGF_RampCI"' in t for t in texts)
    assert any("WString[20]" in t for t in texts)
