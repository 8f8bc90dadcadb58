"""Read an importer's result: CSV as the usual tools write it, Parquet, or a table in memory.

What is understood, so the same judge reads fmpy, both fmusims, fmuCheck, FMI4j, libcosim,
Ecos and fmi-cross-check results:

- a delimiter of ``,``, ``;`` (then also with decimal commas) or tab (the most frequent one in
  the header), or blanks;
- names quoted or bare, with blanks around them; ``#`` comment lines and blank lines skipped;
- an instance prefix, ``pend.theta``, ``pend::theta`` or ``pend/theta``, and a trailing
  annotation in brackets, ``theta [rad]`` or libcosim's ``theta [3 REAL OUTPUT]``;
- a time column called ``time``, ``Time`` or ``t`` (any case); other columns (Ecos'
  ``iterations``, libcosim's ``StepCount``, ``x``, ``y``, ...) are ignored;
- any subset of ``theta``, ``omega``, ``theta_exact``, ``omega_exact`` (at least one).

For CSV, each column's print format is recognised (fixed decimals as ``%f``, or significant
digits as ``%g``, at least 6), and each value's resolution is half a unit in its last printed
place (none from 15 significant digits on), so the checks can tell a rounded print from a
wrong value.
"""

from __future__ import annotations

import csv
import io
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

VARIABLES: tuple[str, ...] = ("theta", "omega", "theta_exact", "omega_exact")
TIME_NAMES = ("time", "t")
_PREFIX = re.compile(r"^(?P<instance>.*?)(?:::|\.|/)(?P<name>[^.:/]+)$")
_ANNOTATION = re.compile(r"\s*[\[(][^\])]*[\])]\s*$")


class ReadError(ValueError):
    """The input cannot be read as a result: one line saying why."""


@dataclass(frozen=True)
class Result:
    """A result as the judge needs it.

    Attributes
    ----------
    time : numpy.ndarray
        The times, as written.
    values : dict of str to numpy.ndarray
        The variables found (keys among :data:`VARIABLES`).
    resolution : dict of str to numpy.ndarray
        Per variable and for ``"time"``: half a unit in the last printed digit of each value
        (0 where the value is stored in binary, as in Parquet or a DataFrame).
    columns : dict of str to str
        The column name each variable was taken from, and ``"time"``'s.
    instance : str
        The instance prefix of the columns used ("" when the names were bare).
    source : str
        A name for the input (the file name, or the type of the object).
    formats : dict of str to Format, or None
        How each column was printed (None: stored in binary).
    """

    time: np.ndarray
    values: dict[str, np.ndarray]
    resolution: dict[str, np.ndarray]
    columns: dict[str, str]
    instance: str
    source: str
    formats: dict[str, Format] | None = None

    @property
    def rows(self) -> int:
        """Number of rows."""
        return int(self.time.size)


def _split_name(raw: str) -> tuple[str, str]:
    """(instance, variable) of a column header: quotes, blanks and an annotation removed."""
    name = raw.strip().strip('"\'').strip()
    name = _ANNOTATION.sub("", name)
    match = _PREFIX.match(name)
    if match and match.group("name") in VARIABLES + TIME_NAMES + ("Time",):
        return match.group("instance").strip("{}"), match.group("name")
    return "", name


DEFAULT_PRECISION = 6
"""C's and C++'s default precision (``%g``, ``std::ostream``): no tool prints fewer significant
digits, so a column whose values happen to be short (0.01, 9.99) is taken as printed with 6."""


@dataclass(frozen=True)
class Format:
    """How a column was printed: ``decimals`` fixed digits after the point (``%f``), else
    ``digits`` significant digits (``%g``; 17 for a round-trip print)."""

    decimals: int | None
    digits: int

    @classmethod
    def of(cls, cells: list[str]) -> Format:
        """The format of a column from its cells."""
        digits, decimals = 0, set()
        for cell in cells:
            text = cell.strip().strip('"').lower()
            mantissa, exponent_mark, _ = text.partition("e")
            mantissa = mantissa.lstrip("+-")
            significant = mantissa.replace(".", "").lstrip("0")
            digits = max(digits, len(significant) if significant.isdigit() else 0)
            decimals.add(len(mantissa.split(".", 1)[1]) if "." in mantissa and not exponent_mark else -1)
        fixed = decimals.pop() if len(decimals) == 1 else -1
        return cls(fixed if fixed > 0 else None, max(digits, DEFAULT_PRECISION))

    def resolution(self, values: np.ndarray) -> np.ndarray:
        """Half a unit in the last printed place of each value (0 from 15 significant digits on,
        which round-trip a double closely enough)."""
        if self.decimals is not None:
            return np.full(values.size, 0.5 * 10.0 ** -self.decimals)
        if self.digits >= 15:
            return np.zeros(values.size)
        with np.errstate(divide="ignore", invalid="ignore"):
            exponent = np.floor(np.log10(np.abs(values)))
        exponent = np.where(np.isfinite(exponent), exponent, 0.0)
        return np.where(values == 0, 0.0, 0.5 * 10.0 ** (exponent - self.digits + 1))

    def describe(self) -> str:
        """"%.6f" or "6 significant digits"."""
        return f"%.{self.decimals}f" if self.decimals is not None else f"{self.digits} significant digits"


def _pick(names: list[str], instance: str | None, source: str) -> tuple[int, dict[str, int], str]:
    """Index of the time column, indexes of the variables, and the instance used."""
    split = [_split_name(n) for n in names]
    time_index = next((i for i, (_, v) in enumerate(split) if v.lower() in TIME_NAMES), None)
    if time_index is None:
        raise ReadError(f"{source}: no time column (looked for time, Time, t among {', '.join(names[:8])})")
    instances = sorted({inst for inst, v in split if v in VARIABLES})
    if not instances:
        raise ReadError(f"{source}: none of {', '.join(VARIABLES)} among the columns ({', '.join(names[:8])})")
    if instance is None:
        if len(instances) > 1:
            raise ReadError(f"{source}: several instances ({', '.join(repr(i) for i in instances)}): "
                            f"choose one with --instance NAME")
        instance = instances[0]
    elif instance not in instances:
        raise ReadError(f"{source}: no instance {instance!r} (found {', '.join(repr(i) for i in instances)})")
    picked: dict[str, int] = {}
    for i, (inst, var) in enumerate(split):
        if inst == instance and var in VARIABLES:
            if var in picked:
                raise ReadError(f"{source}: two columns for {var!r} ({names[picked[var]]!r}, {names[i]!r})")
            picked[var] = i
    return time_index, picked, instance


def _delimiter(header: str) -> str | None:
    counts = {d: header.count(d) for d in (",", ";", "\t")}
    best = max(counts, key=lambda d: counts[d])
    return best if counts[best] else None


def read_csv_text(text: str, source: str, instance: str | None = None) -> Result:
    """Parse CSV text (see the module's description) into a :class:`Result`."""
    lines = [line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        raise ReadError(f"{source}: empty (no header, no rows)")
    delimiter = _delimiter(lines[0])
    if delimiter is None:
        rows = [line.split() for line in lines]
    else:
        rows = list(csv.reader(io.StringIO("\n".join(lines)), delimiter=delimiter, skipinitialspace=True))
    header, body = rows[0], rows[1:]
    if not body:
        raise ReadError(f"{source}: a header and no rows")
    time_index, picked, used = _pick(header, instance, source)
    wanted = {"time": time_index, **picked}
    numbers = {name: np.empty(len(body)) for name in wanted}
    for r, row in enumerate(body):
        if len(row) != len(header):
            raise ReadError(f"{source}: row {r + 2} has {len(row)} fields, the header {len(header)}")
        for name, c in wanted.items():
            cell = row[c].strip().strip('"')
            if delimiter == ";":  # a semicolon file may use the decimal comma (Excel in most locales)
                cell = cell.replace(",", ".")
                row[c] = cell
            try:
                numbers[name][r] = float(cell)
            except ValueError:
                raise ReadError(f"{source}: row {r + 2}, column {header[c].strip()!r}: not a number: {cell!r}") from None
    columns = {name: header[c].strip().strip('"') for name, c in wanted.items()}
    formats = {name: Format.of([row[c] for row in body]) for name, c in wanted.items()}
    if all(f.decimals is None and f.digits >= 15 for n, f in formats.items() if n != "time"):
        formats["time"] = Format(None, 17)  # one round-trip formatter: short times are exact decimals
    resolution = {name: formats[name].resolution(values) for name, values in numbers.items()}
    return Result(numbers.pop("time"), numbers, resolution, columns, used, source, formats)


def _from_columns(columns: dict[str, np.ndarray], source: str, instance: str | None) -> Result:
    names = list(columns)
    time_index, picked, used = _pick(names, instance, source)
    time_name = names[time_index]
    try:
        time = np.asarray(columns[time_name], dtype=float)
        values = {v: np.asarray(columns[names[i]], dtype=float) for v, i in picked.items()}
    except (TypeError, ValueError) as error:
        raise ReadError(f"{source}: a column is not numeric ({error})") from None
    if time.ndim != 1 or time.size == 0:
        raise ReadError(f"{source}: no rows")
    resolution = {name: np.zeros(time.size) for name in ["time", *values]}
    return Result(time, values, resolution, {"time": time_name, **{v: names[i] for v, i in picked.items()}},
                  used, source)


def read_result(data: Any, instance: str | None = None) -> Result:
    """Read a result from a file or from memory.

    Parameters
    ----------
    data : str, Path, pandas.DataFrame, numpy structured array or mapping of name to array
        A CSV or Parquet file (Parquet recognised by its ``PAR1`` signature), or a table.
    instance : str, optional
        The instance whose columns to use when the result holds several (``pend1.theta``,
        ``pend2.theta``); required then.

    Returns
    -------
    Result

    Raises
    ------
    ReadError
        With one line, when the input cannot be read or holds no usable columns.
    """
    if isinstance(data, (str, Path)):
        path = Path(data)
        try:
            raw = path.read_bytes()
        except OSError as error:
            raise ReadError(f"{path}: {error.strerror or error}") from None
        if raw[:4] == b"PAR1":
            import pyarrow.parquet as pq  # noqa: PLC0415
            try:
                table = pq.read_table(path)
            except Exception as error:  # noqa: BLE001 (pyarrow raises many kinds)
                raise ReadError(f"{path}: not a readable Parquet file ({error})") from None
            return _from_columns({n: table.column(n).to_numpy() for n in table.column_names}, str(path), instance)
        try:
            text = raw.decode("utf-8-sig")
        except UnicodeDecodeError:
            raise ReadError(f"{path}: not a text (CSV) or Parquet file") from None
        return read_csv_text(text, str(path), instance)
    if hasattr(data, "columns") and hasattr(data, "__getitem__"):  # a pandas DataFrame
        return _from_columns({str(c): np.asarray(data[c]) for c in data.columns}, type(data).__name__, instance)
    if isinstance(data, np.ndarray) and data.dtype.names:
        return _from_columns({n: data[n] for n in data.dtype.names}, "structured array", instance)
    if isinstance(data, dict):
        return _from_columns({str(k): np.asarray(v) for k, v in data.items()}, "mapping", instance)
    raise ReadError(f"cannot read a result from a {type(data).__name__}: give a CSV or Parquet path or a DataFrame")


def describe_digits(result: Result) -> str:
    """"printed with N significant digits" or "stored in binary"."""
    if result.formats is None:
        return "stored in binary"
    coarse = {n: f for n, f in result.formats.items() if f.decimals is not None or f.digits < 15}
    if not coarse:
        return "printed in full precision"
    kinds: dict[str, list[str]] = {}
    for name, form in coarse.items():
        kinds.setdefault(form.describe(), []).append(result.columns[name])
    return "printed with " + "; ".join(f"{k} ({', '.join(v)})" for k, v in kinds.items())


__all__ = ["ReadError", "Result", "VARIABLES", "describe_digits", "read_result", "read_csv_text"]
