"""CSV text that a spreadsheet shows as written and never runs, and cells read back as typed.

Contents:
    csv_text(rows, columns)   every CSV the grader writes: pandas, "\\n" line endings, inert cells
    csv_file(text)            the bytes of a CSV file: UTF-8 after a byte-order mark, for Excel
    inert(value)              a cell no spreadsheet runs as a formula, on one row
    typed(cell)               a cell as a person typed it, from one :func:`inert` wrote

Two things make a cell dangerous. Text that starts a formula (=, +, -, @, a tab or a line
break first: =HYPERLINK(…) or +cmd|… typed as an answer or a name) is written after an
apostrophe, which spreadsheets read as "text". A line break inside a cell must be quoted, or the
rest of the cell starts a row of its own, and with it possibly a formula: the csv module quotes
a cell holding the line ending it writes ("\\n"), but not a bare "\\r", which Excel and
LibreOffice also end a row at. So every line break in a cell is written as "\\n", and quoted.
Inside quotes a spreadsheet keeps the lines in one cell whose text starts with its first line,
so only a cell's start needs the apostrophe.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence

__all__ = ["csv_file", "csv_text", "inert", "typed"]

_FORMULA_START = ("=", "+", "-", "@", "\t", "\r", "\n")


def csv_text(rows: Iterable[Mapping | Sequence], columns: Sequence[str]) -> str:
    """``rows`` (each a mapping by column, or its cells in order) as CSV text under the header
    ``columns``, with every cell made :func:`inert`."""
    # Imported here, its only use: pandas takes half a second to load, which `grader check`
    # and `grader serve`, which write no CSV, would otherwise spend on every start.
    import pandas

    return pandas.DataFrame(rows, columns=list(columns)).map(inert).to_csv(index=False, lineterminator="\n")


def csv_file(text: str) -> bytes:
    """``text`` as the bytes of a CSV file: UTF-8 after a byte-order mark.

    Excel opens a CSV without one as Windows-1252, so a student's θ̇ or Müller shows as Î¸Ì‡ or
    MÃ¼ller; with it, Excel reads UTF-8. Canvas and Moodle imports skip the mark, and so do our
    readers (``utf-8-sig``).

    >>> csv_file("id,θ\\n")
    b'\\xef\\xbb\\xbfid,\\xce\\xb8\\n'
    """
    return text.encode("utf-8-sig")


def inert(value):
    """A cell no spreadsheet runs: line breaks as "\\n", and text that would start a formula after an apostrophe.

    >>> inert("=HYPERLINK('http://x')"), inert("-m g l cos θ"), inert(-1.5), inert("s1")
    ("'=HYPERLINK('http://x')", "'-m g l cos θ", -1.5, 's1')
    >>> inert("Bob\\r=1+2"), inert("T = 1\\r\\nV = 2")
    ('Bob\\n=1+2', 'T = 1\\nV = 2')
    """
    if not isinstance(value, str):
        return value
    value = value.replace("\r\n", "\n").replace("\r", "\n")
    return "'" + value if value.startswith(_FORMULA_START) else value


def typed(cell: str) -> str:
    """A cell as a person typed it, from one :func:`inert` wrote (its apostrophe removed).

    >>> typed("'-s1"), typed("'tis"), typed("s1")
    ('-s1', "'tis", 's1')
    """
    return cell[1:] if cell.startswith("'") and cell[1:].startswith(_FORMULA_START) else cell
