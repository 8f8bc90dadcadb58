"""Write and read column tables as CSV or Parquet (through pyarrow; no pandas needed)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pyarrow as pa
import pyarrow.csv as pa_csv
import pyarrow.parquet as pq

from pendulum_fmu.output.atomic import write_whole

FORMATS: tuple[str, ...] = (".csv", ".parquet")
ARROW_TYPES: dict[str, pa.DataType] = {"float": pa.float64(), "int": pa.int64(), "str": pa.string()}


def schema_of(kinds: Mapping[str, str]) -> pa.Schema:
    """An Arrow schema from column -> ``float``/``int``/``str``."""
    return pa.schema([(name, ARROW_TYPES[kind]) for name, kind in kinds.items()])


def to_arrow(columns: Mapping[str, Sequence[Any] | np.ndarray], metadata: Mapping[str, str] | None = None,
             kinds: Mapping[str, str] | None = None) -> pa.Table:
    """Build an Arrow table; None in a column becomes a null (an empty CSV cell).

    ``kinds`` (column -> ``float``/``int``/``str``) fixes the types, so that a float column
    whose values happen to be whole numbers stays float, and an all-empty one keeps its type.
    """
    def array(name: str, values: Sequence[Any] | np.ndarray) -> pa.Array:
        kind = None if kinds is None else ARROW_TYPES[kinds[name]]
        return pa.array(values if isinstance(values, np.ndarray) else list(values), type=kind)

    table = pa.table({name: array(name, values) for name, values in columns.items()})
    if metadata:
        table = table.replace_schema_metadata({key: str(value) for key, value in metadata.items()})
    return table


def write_table(columns: Mapping[str, Sequence[Any] | np.ndarray], path: Path,
                metadata: Mapping[str, str] | None = None, kinds: Mapping[str, str] | None = None) -> Path:
    """Write the columns to ``path``, as Parquet or CSV by its suffix.

    Parameters
    ----------
    columns : mapping of str to sequence
        Equal-length columns, in output order.
    path : Path
        Ends in ``.csv`` or ``.parquet``.
    metadata : mapping of str to str, optional
        Key-value notes stored in the Parquet schema (a CSV has no place for them).
    kinds : mapping of str to str, optional
        Column types, see :func:`to_arrow`.

    Returns
    -------
    Path
        ``path``.
    """
    suffix = path.suffix.lower()
    if suffix not in FORMATS:
        raise ValueError(f"{path}: the suffix must be one of {', '.join(FORMATS)}")
    table = to_arrow(columns, metadata, kinds)
    if suffix == ".parquet":
        return write_whole(path, lambda temporary: pq.write_table(table, temporary))
    return write_whole(path, lambda temporary: pa_csv.write_csv(table, temporary))


def read_table(path: Path, kinds: Mapping[str, str] | None = None) -> pa.Table:
    """Read a table written by :func:`write_table`.

    Parameters
    ----------
    path : Path
        A ``.csv`` or ``.parquet`` file.
    kinds : mapping of str to str, optional
        Column types for a CSV (a Parquet file carries its own); without them pyarrow
        infers the types, and reads a float column of whole numbers as integers.
    """
    if path.suffix.lower() == ".parquet":
        return pq.read_table(path)
    options = None if kinds is None else pa_csv.ConvertOptions(column_types=schema_of(kinds))
    return pa_csv.read_csv(path, convert_options=options)
