"""Read an importer's result: CSV as the usual tools write it, Parquet, or a table in memory.

What is understood, so the same judge reads fmpy, both fmusims, fmuCheck, FMI4j, libcosim,
Ecos and fmi-cross-check results, and this package's own ``simulate -o``:

- a delimiter of ``,``, ``;`` (then also with decimal commas) or tab (the most frequent one in
  the header), or blanks;
- names quoted or bare, with blanks around them; ``#`` comment lines and blank lines skipped;
- an instance prefix, ``pend.theta``, ``pend::theta`` or ``pend/theta``, a trailing
  annotation in brackets, ``theta [rad]`` or libcosim's ``theta [3 REAL OUTPUT]``, and a unit
  suffix as ``simulate`` writes it, ``time_s``, ``theta_rad``, ``omega_rad_s``;
- a time column called ``time``, ``Time`` or ``t`` (any case); other columns (Ecos'
  ``iterations``, libcosim's ``StepCount``, ``x``, ``y``, ...) are ignored; in a pandas
  DataFrame the time may be its index (named as a time column, or unnamed and not the
  default 0, 1, 2, ...);
- any subset of ``theta``, ``omega``, ``theta_exact``, ``omega_exact`` (at least one);
- a CSV file gzipped (``run.csv.gz``, as CI artifacts often are), by its signature.

CSV is parsed by Arrow (``pyarrow.csv``) into strings, only the columns used; the numbers
and the print format are computed on whole columns (:mod:`pendulum_fmu.judge.print_format`).
Each column's print format is recognised (fixed decimals as ``%f``, or significant digits
as ``%g``, at least 6), and each value's resolution is half a unit in its last printed
place (none from 15 significant digits on), so the checks can tell a rounded print from a
wrong value. A file Arrow cannot parse is read line by line, which finds the row to blame.
"""

from __future__ import annotations

import csv
import io
import os
import re
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pyarrow as pa
import pyarrow.compute as pc

from pendulum_fmu.judge.print_format import DEFAULT_PRECISION, FULL_DIGITS, CellCounts, Format, clean_cells

VARIABLES: tuple[str, ...] = ("theta", "omega", "theta_exact", "omega_exact")
TIME_NAMES = ("time", "t")
_PREFIX = re.compile(r"^(?P<instance>.*?)(?:::|\.|/)(?P<name>[^.:/]+)$")
_ANNOTATION = re.compile(r"\s*[\[(][^\])]*[\])]\s*$")
_UNIT = re.compile(r"_(?:rad_per_s|rad_s|rad|s)$")
"""The unit suffixes of ``simulate``'s columns (``time_s``, ``theta_rad``, ``omega_rad_s``)."""
_SKIPPED_LINES = re.compile(rb"^[ \t]*(?:#[^\n]*)?\r?(?:\n|\Z)", re.MULTILINE)
"""A comment line or a blank one, with its end of line."""
_NONBLANK = re.compile(rb"\S")
_BLANK_LINE = re.compile(rb"\n[ \t]+\r?\n")
"""A line of blanks only (Arrow skips an empty line, not one of blanks)."""
HEAD_BYTES = 1 << 16
"""The bytes read to recognise a file (Parquet's signature, the CSV header)."""
GZIP_MAGIC = b"\x1f\x8b"
"""The first two bytes of a gzip file (RFC 1952): a gzipped CSV is read uncompressed."""
PANDAS_INDEX = "__index_level_0__"
"""The column pandas stores an unnamed index in, in Parquet."""


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
    """(instance, variable) of a column header: quotes, blanks, an annotation and a unit
    suffix removed."""
    name = raw.strip().strip('"\'').strip()
    name = _ANNOTATION.sub("", name)
    known = VARIABLES + TIME_NAMES + ("Time",)
    match = _PREFIX.match(name)
    instance = ""
    if match and _bare(match.group("name")) in known:
        instance, name = match.group("instance").strip("{}"), match.group("name")
    return instance, _bare(name)


def _bare(name: str) -> str:
    """``name`` without a unit suffix when what remains is a variable or a time (``theta_rad``
    -> ``theta``; ``theta_error_rad`` stays)."""
    stripped = _UNIT.sub("", name)
    return stripped if stripped != name and stripped.lower() in VARIABLES + TIME_NAMES else name


def _pick(names: list[str], instance: str | None, source: str) -> tuple[int, dict[str, int], str]:
    """Index of the time column, indexes of the variables, and the instance used."""
    split = [_split_name(n) for n in names]
    time_index = next((i for i, (_, v) in enumerate(split) if v.lower() in TIME_NAMES), None)
    if time_index is None and PANDAS_INDEX in names:
        time_index = names.index(PANDAS_INDEX)
    if time_index is None:
        raise ReadError(f"{source}: no time column (looked for time, Time, t among {', '.join(names[:8])})")
    instances = sorted({inst for inst, v in split if v in VARIABLES})
    if not instances:
        raise ReadError(f"{source}: no theta or omega column: none of {', '.join(VARIABLES)} among the columns "
                        f"({', '.join(names[:8])})")
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


def _assemble(numbers: dict[str, np.ndarray], formats: dict[str, Format], columns: dict[str, str], instance: str,
              source: str) -> Result:
    """The :class:`Result` of parsed CSV columns (``"time"`` among them) and their formats."""
    if all(f.decimals is None and f.digits >= FULL_DIGITS for n, f in formats.items() if n != "time"):
        formats["time"] = Format(None, 17)  # one round-trip formatter: short times are exact decimals
    resolution = {name: formats[name].resolution(values) for name, values in numbers.items()}
    time = numbers.pop("time")
    return Result(time, numbers, resolution, columns, instance, source, formats)


def read_csv_text(text: str, source: str, instance: str | None = None) -> Result:
    """Parse CSV text (see the module's description) into a :class:`Result`, line by line:
    slow, but every error names its row."""
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
                raise ReadError(f"{source}: row {r + 2}, column {header[c].strip()!r}: "
                                f"not a number: {cell!r}") from None
    columns = {name: header[c].strip().strip('"') for name, c in wanted.items()}
    formats = {name: Format.of([row[c] for row in body]) for name, c in wanted.items()}
    return _assemble(numbers, formats, columns, used, source)


class _Unparsed(Exception):
    """Arrow could not parse the file: read it line by line for the row to blame."""


def _column_numbers(cells: pa.ChunkedArray, decimal_comma: bool) -> tuple[np.ndarray, CellCounts]:
    """The numbers of one column of CSV cells and the counts of its print format."""
    counts = CellCounts()
    parts = []
    for chunk in cells.chunks:
        text = clean_cells(chunk, decimal_comma)
        try:
            values = pc.cast(text, pa.float64()).to_numpy(zero_copy_only=False)
        except pa.ArrowInvalid:
            raise _Unparsed from None
        counts.add(text, values)
        parts.append(values)
    return (np.concatenate(parts) if parts else np.empty(0)), counts


def read_csv_bytes(raw: bytes, source: str, instance: str | None = None) -> Result:
    """Parse CSV bytes (UTF-8, see the module's description) into a :class:`Result`.

    Arrow reads the used columns as strings; their numbers and print formats are computed
    column by column. Comment lines and lines of blanks are removed first (Arrow skips only
    empty lines). What Arrow still refuses (a short row, a cell that is not a number) goes to
    :func:`read_csv_text`, which names the row.
    """
    if raw.startswith(b"\xef\xbb\xbf"):
        raw = raw[3:]
    raw = raw.lstrip()
    cleaned = b"#" in raw
    if cleaned:
        raw = _SKIPPED_LINES.sub(b"", raw)
    end = raw.find(b"\n")
    header_line, delimiter, header = _header(raw if end < 0 else raw[:end], source)
    body = pa.py_buffer(raw).slice(len(raw) if end < 0 else end + 1)  # no copy
    if delimiter is None:  # blanks: one comma between fields
        body = pa.py_buffer(re.sub(rb"[ \t]+", b",", re.sub(rb"(?m)^[ \t]+|[ \t]+(?=\r?$)", b"",
                                                              body.to_pybytes())))
    if end < 0 or not _NONBLANK.search(raw, end + 1):
        raise ReadError(f"{source}: a header and no rows")
    time_index, picked, used = _pick(header, instance, source)
    wanted = {"time": time_index, **picked}
    try:
        numbers, formats = _parse(body, len(header), delimiter or ",", wanted)
    except _Unparsed:
        if not cleaned and _BLANK_LINE.search(raw):
            return read_csv_bytes(_SKIPPED_LINES.sub(b"", raw), source, instance)
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError:
            raise ReadError(f"{source}: not a text (CSV) or Parquet file") from None
        return read_csv_text(text, source, instance)
    columns = {name: header[c].strip().strip('"') for name, c in wanted.items()}
    return _assemble(numbers, formats, columns, used, source)


def _header(line: bytes, source: str) -> tuple[str, str | None, list[str]]:
    """The header line as text, its delimiter (None: blanks) and its names."""
    try:
        text = line.decode("utf-8").rstrip("\r")
    except UnicodeDecodeError:
        raise ReadError(f"{source}: not a text (CSV) or Parquet file") from None
    if not text.strip():
        raise ReadError(f"{source}: empty (no header, no rows)")
    delimiter = _delimiter(text)
    if delimiter is None:
        return text, None, text.split()
    return text, delimiter, next(csv.reader([text], delimiter=delimiter, skipinitialspace=True))


def read_csv_file(path: Path, head: bytes, instance: str | None = None) -> Result:
    """Parse a CSV file whose first bytes are ``head``: Arrow reads the file itself when it
    begins with its header (no byte order mark, comment or blank line before it) and has a
    delimiter; anything else, or anything Arrow refuses, is read as :func:`read_csv_bytes`."""
    end = head.find(b"\n")
    source = str(path)
    if end > 0 and head[:1] not in (b"\xef", b"#", b" ", b"\t", b"\r"):
        _, delimiter, header = _header(head[:end], source)
        if delimiter is not None:
            time_index, picked, used = _pick(header, instance, source)
            wanted = {"time": time_index, **picked}
            try:
                numbers, formats = _parse(str(path), len(header), delimiter, wanted, skip_rows=1)
            except _Unparsed:
                pass
            else:
                if numbers["time"].size == 0:
                    raise ReadError(f"{source}: a header and no rows")
                columns = {name: header[c].strip().strip('"') for name, c in wanted.items()}
                return _assemble(numbers, formats, columns, used, source)
    try:
        raw = path.read_bytes()
    except OSError as error:
        raise ReadError(f"{path}: {error.strerror or error}") from None
    return read_csv_bytes(raw, source, instance)


def _parse(body: pa.Buffer | str, width: int, delimiter: str, wanted: dict[str, int],
           skip_rows: int = 0) -> tuple[dict[str, np.ndarray], dict[str, Format]]:
    """Numbers and formats of the ``wanted`` columns (name -> index) of the CSV rows in
    ``body`` (bytes, or a file whose first ``skip_rows`` lines are skipped); the columns
    are converted in threads (Arrow and numpy release the interpreter)."""
    import pyarrow.csv as pacsv

    names = [f"c{i}" for i in range(width)]
    used = {name: names[c] for name, c in wanted.items()}
    try:
        table = pacsv.read_csv(pa.BufferReader(body) if isinstance(body, pa.Buffer) else body,
                               read_options=pacsv.ReadOptions(column_names=names, block_size=1 << 24,
                                                              skip_rows=skip_rows),
                               parse_options=pacsv.ParseOptions(delimiter=delimiter, ignore_empty_lines=True),
                               convert_options=pacsv.ConvertOptions(include_columns=sorted(set(used.values())),
                                                                    column_types=dict.fromkeys(used.values(),
                                                                                               pa.string()),
                                                                    strings_can_be_null=False,
                                                                    quoted_strings_can_be_null=False))
    except (pa.ArrowException, UnicodeDecodeError):  # any refusal: the line-by-line reader names it
        raise _Unparsed from None
    with ThreadPoolExecutor(max_workers=min(len(used), os.cpu_count() or 1)) as pool:
        done = {name: pool.submit(_column_numbers, table.column(column), delimiter == ";")
                for name, column in used.items()}
        parsed = {name: future.result() for name, future in done.items()}
    return {name: p[0] for name, p in parsed.items()}, {name: p[1].format() for name, p in parsed.items()}


def _from_columns(columns: dict[str, Any], source: str, instance: str | None) -> Result:
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
    shown = "index" if time_name == PANDAS_INDEX else time_name
    return Result(time, values, resolution, {"time": shown, **{v: names[i] for v, i in picked.items()}},
                  used, source)


def _read_parquet(path: Path, instance: str | None) -> Result:
    """The used columns of a Parquet file (an unnamed pandas index stored with it may be the time)."""
    import pyarrow.parquet as pq

    try:
        names = list(pq.read_schema(path).names)
        time_index, picked, _ = _pick(names, instance, str(path))
        table = pq.read_table(path, columns=[names[time_index], *(names[i] for i in picked.values())])
    except ReadError:
        raise
    except Exception as error:  # noqa: BLE001 (pyarrow raises many kinds)
        raise ReadError(f"{path}: not a readable Parquet file ({error})") from None
    return _from_columns({n: table.column(n).to_numpy() for n in table.column_names}, str(path), instance)


def _frame_columns(frame: Any) -> dict[str, Any]:
    """A pandas DataFrame's columns, and its index as the time when no column is a time: an
    index named as a time column, or an unnamed one that is not the default 0, 1, 2, ..."""
    columns = {str(c): frame[c].to_numpy() for c in frame.columns}
    if any(_split_name(n)[1].lower() in TIME_NAMES for n in columns):
        return columns
    index = frame.index
    name = index.name
    if name is not None and _split_name(str(name))[1].lower() in TIME_NAMES:
        return {str(name): index.to_numpy(), **columns}
    if name is None and type(index).__name__ != "RangeIndex" and getattr(index, "nlevels", 1) == 1:
        return {"time": index.to_numpy(), **columns}
    return columns


def _gunzip(path: Path) -> bytes:
    """The content of a gzipped file (a CSV result as CI artifacts often are)."""
    import gzip
    import zlib

    try:
        with gzip.open(path, "rb") as handle:
            raw = handle.read()
    except (OSError, EOFError, zlib.error) as error:
        raise ReadError(f"{path}: a gzip file that cannot be uncompressed ({error})") from None
    if raw[:4] == b"PAR1":
        raise ReadError(f"{path}: a gzipped Parquet file: uncompress it first (Parquet compresses itself)")
    return raw


def read_result(data: Any, instance: str | None = None) -> Result:
    """Read a result from a file or from memory.

    Parameters
    ----------
    data : str, Path, pandas.DataFrame, numpy structured array or mapping of name to array
        A CSV or Parquet file (Parquet recognised by its ``PAR1`` signature), a gzipped CSV
        file (by its signature ``1f 8b``, whatever its name), or a table.
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
            with path.open("rb") as handle:
                head = handle.read(HEAD_BYTES)
        except OSError as error:
            raise ReadError(f"{path}: {error.strerror or error}") from None
        if head[:4] == b"PAR1":
            return _read_parquet(path, instance)
        if head[:2] == GZIP_MAGIC:
            return read_csv_bytes(_gunzip(path), str(path), instance)
        return read_csv_file(path, head, instance)
    if hasattr(data, "columns") and hasattr(data, "index") and hasattr(data, "__getitem__"):  # a pandas DataFrame
        return _from_columns(_frame_columns(data), type(data).__name__, instance)
    if isinstance(data, np.ndarray) and data.dtype.names:
        return _from_columns({n: data[n] for n in data.dtype.names}, "structured array", instance)
    if isinstance(data, dict):
        return _from_columns({str(k): np.asarray(v) for k, v in data.items()}, "mapping", instance)
    raise ReadError(f"cannot read a result from a {type(data).__name__}: give a CSV or Parquet path or a DataFrame")


def describe_digits(result: Result) -> str:
    """"printed with N significant digits" or "stored in binary"."""
    if result.formats is None:
        return "stored in binary"
    coarse = {n: f for n, f in result.formats.items() if f.decimals is not None or f.digits < FULL_DIGITS}
    if not coarse:
        return "printed in full precision"
    kinds: dict[str, list[str]] = {}
    for name, form in coarse.items():
        kinds.setdefault(form.describe(), []).append(result.columns[name])
    return "printed with " + "; ".join(f"{k} ({', '.join(v)})" for k, v in kinds.items())


__all__ = ["DEFAULT_PRECISION", "Format", "ReadError", "Result", "VARIABLES", "describe_digits", "read_csv_bytes",
           "read_csv_file", "read_csv_text", "read_result"]
