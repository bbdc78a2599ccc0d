"""Opening granmc's HDF5 result files: the format version is checked first (docs/formats/output-format.md).

    from granmc import open_results
    with open_results("run.h5") as f:
        T = f["temperature/mean"][()]

A file of a major version this reader does not know (a record renamed, moved or given another meaning) is
refused with a message, never read with the wrong meaning.
"""
import h5py

FORMAT_MAJOR = 2  # io/output_schema.hpp, output_format_major


class FormatError(ValueError):
    pass


def format_major(f):
    """The major version of an open result file (1: files written before the format carried a version)."""
    version = f.attrs.get("format_version")
    if version is None:
        return 1
    return int(str(version.decode() if isinstance(version, bytes) else version).split(".")[0])


def open_results(path):
    """The HDF5 file at `path`, open for reading, after checking its format version."""
    f = h5py.File(path, "r")
    major = format_major(f)
    if major != FORMAT_MAJOR:
        f.close()
        raise FormatError(f"{path}: output format {major}.x, this reader knows {FORMAT_MAJOR}.x "
                          f"(docs/formats/output-format.md); rerun the scene with this granmc, or read it with the "
                          f"scripts of the granmc that wrote it")
    return f
