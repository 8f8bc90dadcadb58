"""How a CSV column was printed, from its cells, and what that print can resolve.

The cells are measured as Arrow string arrays, every cell at once (``pyarrow.compute`` on
the cells, numpy on their lengths and positions, a byte search for the rare exponent mark):
significant digits of the mantissa (leading zeros, sign and point not counted; trailing
zeros counted: ``1.500`` has 4) and digits after the point when there is no exponent. A
column whose cells all have the same number d > 0 of decimals was printed as ``%.{d}f``;
otherwise with as many significant digits as its longest cell, at least
:data:`DEFAULT_PRECISION`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pyarrow as pa
import pyarrow.compute as pc

DEFAULT_PRECISION = 6
"""C's and C++'s default precision (``%g``, ``std::ostream``): no tool prints fewer significant
digits, so a column whose values happen to be short (0.01, 9.99) is taken as printed with 6."""
FULL_DIGITS = 15
"""From this many significant digits on a print round-trips a double closely enough to count
as exact (resolution 0)."""


def _holds(cells: pa.Array, characters: bytes) -> bool:
    """Whether any cell holds one of ``characters`` (a scan of the array's bytes)."""
    data = cells.buffers()[2]
    if data is None:
        return False
    raw = bytes(data)
    return any(bytes([c]) in raw for c in characters)


def clean_cells(cells: pa.Array, decimal_comma: bool = False) -> pa.Array:
    """The cells without surrounding blanks and double quotes (``"1.5"`` -> ``1.5``), with a
    decimal comma made a point when ``decimal_comma`` (the cells as they are when none of
    these occur)."""
    text = cells if pa.types.is_string(cells.type) else cells.cast(pa.string())
    if _holds(text, b' \t\r\n\v\f"'):
        text = pc.utf8_trim_whitespace(pc.utf8_trim(pc.utf8_trim_whitespace(text), characters='"'))
    if decimal_comma:
        text = pc.replace_substring(text, ",", ".")
    return text


@dataclass
class CellCounts:
    """Running counts over a column's cells, fed batch by batch (:meth:`add`)."""

    digits: int = 0
    """The most significant digits of any cell's mantissa."""
    fewest_decimals: int | None = None
    """The fewest digits after the point of any cell (-1: a cell with an exponent or no point)."""
    most_decimals: int | None = None
    """The most digits after the point of any cell."""

    def add(self, text: pa.Array, values: np.ndarray) -> None:
        """Count the cleaned cells ``text`` (:func:`clean_cells`) whose parsed values are ``values``.

        With n a cell's length, l the length of its lead (sign, zeros and a point before the
        first nonzero digit), e the position of its exponent mark (n without one) and p that
        of its point: the mantissa is the first e bytes; its significant digits are
        e - l, less 1 for a point after the lead (``-0.00120`` has 3, ``1.500`` has 4); its
        decimals n - p - 1 when it has a point and no exponent, else -1. A cell that is not a
        finite number (nan, inf) has no digits.
        """
        if len(text) == 0:
            return
        n = _lengths(text)
        lead = n - _lengths(pc.ascii_ltrim(text, characters="+-0."))
        exponent = _first_byte(text, b"eE")
        point = _found(text, ".")
        mantissa = np.where(exponent >= 0, exponent, n)
        has_point = (point >= 0) & (point < mantissa)
        digits = np.maximum(mantissa - lead - (has_point & (point >= lead)), 0)
        digits = np.where(np.isfinite(values), digits, 0)
        self.digits = max(self.digits, int(digits.max()))
        decimals = np.where(has_point & (exponent < 0), n - point - 1, -1)
        low, high = int(decimals.min()), int(decimals.max())
        self.fewest_decimals = low if self.fewest_decimals is None else min(self.fewest_decimals, low)
        self.most_decimals = high if self.most_decimals is None else max(self.most_decimals, high)

    def format(self) -> Format:
        """The column's :class:`Format`: ``%.{d}f`` when every cell has the same d > 0 decimals."""
        fixed = self.fewest_decimals if self.fewest_decimals == self.most_decimals else None
        return Format(fixed if fixed is not None and fixed > 0 else None, max(self.digits, DEFAULT_PRECISION))


def _found(text: pa.Array, part: str) -> np.ndarray:
    """Where ``part`` first occurs in each cell, in bytes (-1: nowhere)."""
    return pc.find_substring(text, part).to_numpy(zero_copy_only=False)


def _first_byte(text: pa.Array, characters: bytes) -> np.ndarray:
    """Where the first of ``characters`` occurs in each cell, in bytes (-1: nowhere).

    When they are rare (an exponent mark in a few cells), the array's bytes are searched
    for them and each hit is mapped to its cell; else every cell is searched.
    """
    _, offsets, data = text.buffers()
    if data is None:
        return np.full(len(text), -1, dtype=np.int32)
    bounds = np.frombuffer(offsets, dtype=np.int32)[text.offset:text.offset + len(text) + 1]
    raw = data.to_pybytes()[:bounds[-1]]
    present = [bytes([c]) for c in characters if bytes([c]) in raw[bounds[0]:]]
    if sum(raw.count(c, bounds[0]) for c in present) > len(text) // 64:
        return _earliest([_found(text, c.decode()) for c in present])
    hits = sorted(i for c in present for i in _positions(raw, c, int(bounds[0])))
    found = np.full(len(text), -1, dtype=np.int32)
    if hits:
        where = np.array(hits)
        cells = np.searchsorted(bounds, where, side="right") - 1
        cells, first = np.unique(cells, return_index=True)
        found[cells] = where[first] - bounds[cells]
    return found


def _earliest(found: list[np.ndarray]) -> np.ndarray:
    """The earliest of several positions per cell (-1: none)."""
    big = np.iinfo(np.int32).max
    earliest = np.min([np.where(f < 0, big, f) for f in found], axis=0)
    return np.where(earliest == big, -1, earliest).astype(np.int32)


def _positions(raw: bytes, part: bytes, start: int) -> list[int]:
    """Every position of ``part`` in ``raw`` from ``start`` on."""
    out = []
    i = raw.find(part, start)
    while i >= 0:
        out.append(i)
        i = raw.find(part, i + 1)
    return out


def _lengths(text: pa.Array) -> np.ndarray:
    """Each cell's length in bytes (numbers are ASCII: bytes and characters alike)."""
    return pc.binary_length(text).to_numpy(zero_copy_only=False)


@dataclass(frozen=True)
class Format:
    """How a column was printed: ``decimals`` fixed digits after the point (``%f``), else
    ``digits`` significant digits (``%g``; 17 for a round-trip print)."""

    decimals: int | None
    digits: int

    @classmethod
    def of(cls, cells: Sequence[str]) -> Format:
        """The format of a column from its cells (as written, blanks and quotes allowed)."""
        text = clean_cells(pa.array(list(cells), type=pa.string()))
        try:
            values = pc.cast(text, pa.float64()).to_numpy(zero_copy_only=False)
        except pa.ArrowInvalid:
            values = np.array([_number(str(c)) for c in text.to_pylist()])
        counts = CellCounts()
        counts.add(text, values)
        return counts.format()

    def resolution(self, values: np.ndarray) -> np.ndarray:
        """Half a unit in the last printed place of each value (0 from :data:`FULL_DIGITS`
        significant digits on)."""
        if self.decimals is not None:
            return np.full(values.size, 0.5 * 10.0 ** -self.decimals)
        if self.digits >= FULL_DIGITS:
            return np.zeros(values.size)
        with np.errstate(divide="ignore", invalid="ignore"):
            exponent = np.floor(np.log10(np.abs(values)))
        exponent = np.where(np.isfinite(exponent), exponent, 0.0)
        return np.where(values == 0, 0.0, 0.5 * 10.0 ** (exponent - self.digits + 1))

    def describe(self) -> str:
        """"%.6f" or "6 significant digits"."""
        return f"%.{self.decimals}f" if self.decimals is not None else f"{self.digits} significant digits"


def _number(cell: str) -> float:
    try:
        return float(cell)
    except ValueError:
        return float("nan")


__all__ = ["DEFAULT_PRECISION", "FULL_DIGITS", "CellCounts", "Format", "clean_cells"]
