"""The only ways text of an SCL source reaches an output (docs/scl.md §4): one function per
target. The generated C, the modelDescription.xml (printed by src/describe.c from the C strings of
the interface table) and the documentation's HTML take a title, a comment or a name only through
these, so that no source can close a comment or a string and put its own C into an FMU, nor
make a description or a page that is not well-formed.

- c_comment: the inside of a one-line C comment `/* ... */`.
- c_string: a C string literal holding the text's UTF-8 bytes exactly (trigraphs included).
- c_format: the same as the format of a printf (a `%` doubled).
- xml_text: what describe.c may print into an XML attribute (it escapes & < > " itself).
- html_text: the text of an HTML element or attribute.
"""

from __future__ import annotations

import html
import re

# what XML 1.0 allows (its Char production), and within it what a one-line comment keeps
_NOT_XML = re.compile("[^\t\n\r\u0020-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")
_CONTROL = re.compile("[\u0000-\u001f\u007f-\u009f\u2028\u2029]")
# describe.c writes an array element's index for {i} and {i+1} in a description
_PLACEHOLDER = re.compile(r"\{(i|i\+1)\}")
# describe.c copies at most 499 bytes of a description: a longer one is cut here, at a whole
# character, so that no UTF-8 sequence is split
XML_BYTES = 400
COMMENT_CHARACTERS = 100


def _shorten(text: str, limit: int) -> str:
    return text if len(text) <= limit else text[: limit - 3] + "..."


def c_comment(text: str) -> str:
    """text as the inside of a one-line C comment: no line break (so a backslash or a trigraph
    ??/ splices no line), nothing that ends the comment or starts one (`*/`, `/*`), shortened
    to COMMENT_CHARACTERS."""
    text = _CONTROL.sub(" ", _NOT_XML.sub("?", text))
    text = _shorten(text.strip(), COMMENT_CHARACTERS)
    # a / next to a * may close or open a comment: keep them apart
    return re.sub(r"\*(?=/)|/(?=\*)", lambda m: m.group(0) + " ", text)


def c_string(text: str) -> str:
    """A C string literal of text's UTF-8 bytes: printable ASCII as it is, \\ " ? escaped
    (so no trigraph), everything else as three-digit octal escapes."""
    out = []
    for byte in text.encode("utf-8", "surrogatepass"):
        c = chr(byte)
        if c in '\\"?':
            out.append("\\" + c)
        elif 0x20 <= byte < 0x7F:
            out.append(c)
        else:
            out.append(f"\\{byte:03o}")
    return '"' + "".join(out) + '"'


def c_format(text: str) -> str:
    """text as the format string of snprintf: c_string with every % doubled."""
    return c_string(text.replace("%", "%%"))


def xml_text(text: str) -> str:
    """text that describe.c prints into modelDescription.xml as it is: only characters XML
    allows (the others become ?), no line break, no {i} placeholder, at most XML_BYTES of
    UTF-8."""
    text = _CONTROL.sub(" ", _NOT_XML.sub("?", text)).strip()
    text = _PLACEHOLDER.sub(lambda m: "{ " + m.group(1) + " }", text)
    data = text.encode("utf-8")
    if len(data) > XML_BYTES:  # cut at a whole character
        text = data[: XML_BYTES - 3].decode("utf-8", "ignore") + "..."
    return text


def xml_name(name: str) -> str:
    """An FMI variable name, which describe.c prints with & < > " escaped: the checks let no
    control character into a name (docs/scl.md §2), so every character is one XML allows."""
    if _CONTROL.search(name) or _NOT_XML.search(name):
        raise AssertionError(f"an FMI name the checks should have refused: {name!r}")
    return name


def html_text(text: str) -> str:
    """text inside an HTML element or a quoted attribute: & < > " ' escaped, characters XML
    does not allow replaced by ?, so that the page is well-formed XML as well."""
    return html.escape(_NOT_XML.sub("?", text), quote=True)
