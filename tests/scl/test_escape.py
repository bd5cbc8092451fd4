"""Source text reaches the C, the modelDescription.xml and the documentation only through
lgf_fmus.scl.escape (docs/scl.md §4): hostile text in every place of an SCL source that an
output may take text from is compiled, or refused at a place of the source; where it compiles,
the generated C is the C of the same source without it (comments and descriptions aside), and
the XML and the HTML are well-formed."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
import zipfile

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import escape
from lgf_fmus.scl.cnames import identifier
from tests.scl.driver import compile_text

# every place of the source where free text stands, as {PLACE}
TEMPLATE = """TYPE "{UDT_NAME}"
TITLE = {UDT_TITLE}
VERSION : 0.1
   STRUCT
      x : Int;   // {UDT_MEMBER}
   END_STRUCT;
END_TYPE
DATA_BLOCK "Settings"
TITLE = {DB_TITLE}
{{ S7_Optimized_Access := '{PRAGMA}' }}
   VAR
      limit : Int := 3;   // {DB_MEMBER}
   END_VAR
BEGIN
END_DATA_BLOCK
FUNCTION "{FC_NAME}" : Int
TITLE = {FC_TITLE}
   VAR_INPUT
      x : Int;   // {FC_INPUT}
   END_VAR
BEGIN
    REGION {FC_REGION}
        #"{FC_NAME}" := #x * 2;  // {FC_LINE}
    END_REGION
END_FUNCTION
FUNCTION_BLOCK "Fb"
TITLE = {TITLE}
{{ S7_Optimized_Access := 'TRUE' }}
VERSION : 0.1
AUTHOR : {AUTHOR}
FAMILY : {FAMILY}
NAME : {NAME}
   VAR_INPUT
      i : Int;   // {INPUT}
   END_VAR
   VAR_OUTPUT
      o : Int;   // {OUTPUT}
   END_VAR
   VAR_IN_OUT
      io : Int;  // {IN_OUT}
   END_VAR
   VAR
      s : Int;   // {STATIC}
      "{STATIC_NAME}" : Int;
      p : "{UDT_NAME}";  // {UDT_STATIC}
      a : ARRAY[0..1] OF Real;  // {ARRAY}
      st : STRUCT  // {STRUCT}
         y : Bool;  // {STRUCT_MEMBER}
      END_STRUCT;
   END_VAR
   VAR_TEMP
      t : Int;   // {TEMP}
   END_VAR
   VAR CONSTANT
      k : Int := 2;  // {CONSTANT}
   END_VAR
BEGIN
    REGION {REGION}
        (* {PAREN_COMMENT} *)
        /* {SLASH_COMMENT} */
        #t := #i * #k; // {LINE_COMMENT}
    END_REGION
    #s := "{FC_NAME}"(x := #t) + "Settings".limit;
    #p.x := #s;
    #o := #p.x;
END_FUNCTION_BLOCK
"""
PLACES = sorted(set(re.findall(r"(?<!\{)\{([A-Z_]+)\}", TEMPLATE)))
# the quoted names: of any character but a control character (docs/scl.md §2), which the C
# holds as mangled identifiers ([DEC-NAME-C]) and the XML as text
NAMES = {"UDT_NAME", "FC_NAME", "STATIC_NAME"}
PLAIN = "Plain"

HOSTILE = {
    "injection": "a */ #error injected /*",
    "comment-open": "/* x",
    "star-slash": "*/*/",
    "backslash": "a \\",
    "newline": "a\nb",
    "carriage-return": "a\rb",
    "quotes": "say \"hi\" 'there'",
    "trigraph": "what??/ ??= ??' ??",
    "nul": "a\0b",
    "non-ascii": "Grüße € 😀 \u2028 \u00a0 \ufeff",
    "long": "x" * 20000,
    "format": "%s %n %%",
    "markup": '<tag a="1"> & ]]> --> &amp;',
    "placeholder": "{i} {i+1}",
    "controls": "\x01\x1b[31m\x7f\x85\x0c",
    "braces": "} { ' '",
}


def source(values: dict) -> str:
    return TEMPLATE.format(**{p: values.get(p, PLAIN) for p in PLACES})


# The arguments of interface.c's macros (src/core/model.h) that hold a description, or the GUID
# (a hash of the source text): by their place in the call.
TEXT_ARGUMENTS = {"ROW": (6,), "NAMED_ROW": (7,), "BLOCK_MODEL": (1, 3)}
ARGUMENT = re.compile(r'(?:"(?:[^"\\]|\\.)*"|\((?:"(?:[^"\\]|\\.)*"|[^"()])*\)|[^",()])+')


def without_texts(c: str) -> str:
    """c with the descriptions and the GUID of its macro calls replaced by TEXT."""
    calls = re.compile(r"\b(" + "|".join(TEXT_ARGUMENTS) + r")\(")
    out, at = [], 0
    for m in calls.finditer(c):
        if m.start() < at:
            continue
        arguments, end = [], m.end()
        while c[end] != ")":
            argument = ARGUMENT.match(c, end)
            arguments.append(argument.group())
            end = argument.end() + (c[argument.end()] == ",")
        texts = TEXT_ARGUMENTS[m.group(1)]
        arguments = ["TEXT" if i in texts else a.strip() for i, a in enumerate(arguments)]
        out += [c[at : m.end()], ",".join(arguments)]
        at = end
    return "".join(out) + c[at:]


def normal(c: str) -> str:
    """The C without its comments, descriptions and GUID, its layout aside."""
    c = re.sub(r"/\*.*?\*/", "", without_texts(c), flags=re.S)
    return " ".join(c.split())  # clang-format lays the C out after the comments' lengths


def shape(c: str) -> str:
    """The C with every string $ and every identifier I, a named row as a row (a static of a
    quoted name has its FMI name apart from its C name: NAMED_ROW(vr, "'a b'", q_a_20_b, ...))."""
    c = re.sub(r'"(?:[^"\\]|\\.)*"', "$", c)
    c = re.sub(r"\s", "", re.sub(r"\b[A-Za-z_][A-Za-z0-9_]*\b", "I", c))
    return re.sub(r"I\((\d+),\$,I,", r"I(\1,I,", c)


def generate(tmp_path, text: str) -> dict:
    path = tmp_path / "hostile.scl"
    path.write_text(text, encoding="utf-8")
    return scl.generate_c([path], block="Fb")


@pytest.fixture(scope="module")
def plain(tmp_path_factory):
    c = generate(tmp_path_factory.mktemp("plain"), source({}))
    return {k: normal(v) for k, v in c.items() if not k.startswith("documentation")}


@pytest.fixture(scope="module")
def outcomes(tmp_path_factory):
    """{(place, hostile): the generated files, or the SclError that refused it}."""
    tmp = tmp_path_factory.mktemp("hostile")
    found = {}
    for place in PLACES:
        for hostile, text in HOSTILE.items():
            try:
                found[place, hostile] = generate(tmp, source({place: text}))
            except scl.SclError as e:
                found[place, hostile] = e
    return found


@pytest.mark.parametrize("hostile", sorted(HOSTILE))
def test_hostile_text_in_every_place_compiles_to_the_same_c_or_is_refused(plain, outcomes, hostile):
    compiled = []
    for place in PLACES:
        c = outcomes[place, hostile]
        if isinstance(c, scl.SclError):
            # refused at a place of the source (a name of other characters, a comment or a
            # header that a line break or a closing mark ends early)
            assert c.loc is not None and c.loc.line >= 1, (place, str(c))
            continue
        compiled.append(place)
        if place in NAMES:  # the C of the same shape, the name an identifier in it
            for name, code in c.items():
                if not name.startswith("documentation"):
                    assert shape(normal(code)) == shape(plain[name]), (place, name)
            if place == "STATIC_NAME":
                assert identifier(HOSTILE[hostile]) in c["blocks/Fb/block.h"]
            continue
        for name, code in c.items():
            if name.startswith("documentation"):
                continue
            assert normal(code) == plain[name], (place, name)
    # the places of free text take any text on one line
    free = {"TITLE", "REGION", "INPUT", "STATIC", "LINE_COMMENT", "FC_REGION", "UDT_TITLE"}
    if "\n" not in HOSTILE[hostile] and "\r" not in HOSTILE[hostile]:
        assert free <= set(compiled)


def test_the_injection_is_a_plain_comment(tmp_path):
    """The REGION title that closed its C comment: now the text of one comment."""
    fmu = compile_text(tmp_path, source({"REGION": HOSTILE["injection"]}), "Fb")
    block_c = zipfile.ZipFile(fmu).read("sources/blocks/Fb/block.c").decode()
    (line,) = [x for x in block_c.splitlines() if "injected" in x]
    assert line.strip() == "/* REGION a * / #error injected / * */"


@pytest.mark.parametrize("fmi", [2, 3])
def test_the_xml_and_the_html_are_well_formed(tmp_path, outcomes, fmi):
    """Every hostile text that compiles at a place, all at once, in a built FMU."""
    values = {}
    for place in PLACES:
        accepted = [
            text
            for hostile, text in HOSTILE.items()
            if not isinstance(outcomes[place, hostile], scl.SclError)
        ]
        values[place] = " ".join(accepted) if accepted else PLAIN
    fmu = compile_text(tmp_path, source(values), "Fb", fmi=fmi)
    z = zipfile.ZipFile(fmu)
    description = ET.fromstring(z.read("modelDescription.xml"))
    assert description.get("description").startswith("Fb, compiled from SCL by lgf-fmus: ")
    names = [v.get("name") for v in description.iter() if v.get("name")]
    assert "s" in names and "p.x" in names
    if fmi == 3:
        ET.fromstring(z.read("sources/buildDescription.xml"))
    page = z.read("documentation/index.html").decode()
    assert page.startswith("<!DOCTYPE html>\n")
    ET.fromstring(page.split("\n", 1)[1])


def test_each_escape_function_on_its_own():
    assert escape.c_comment("a */ b /* c") == "a * / b / * c"
    assert escape.c_comment("x\ny\\") == "x y\\"
    assert escape.c_string('a"b\\c??/') == '"a\\"b\\\\c\\?\\?/"'
    assert escape.c_string("ü\0") == '"\\303\\274\\000"'
    assert escape.c_format("100%") == '"100%%"'
    assert escape.xml_text("a\0b{i}\nc") == "a?b{ i } c"
    assert len(escape.xml_text("€" * 1000).encode()) <= escape.XML_BYTES
    assert escape.html_text("<a & 'b'>\x01") == "&lt;a &amp; &#x27;b&#x27;&gt;?"
