"""What the tools' plot scripts share: matplotlib on the Agg backend, their JSON read with one-line
errors, and SVGs written through a temporary file so a failed run leaves no half-written chart.
Imported by tools/liquid_validate/plot_validation.py and tools/liquid_benchmark/plot_benchmark.py."""

import json
import os
import sys


class PlotError(Exception):
    """A problem with the input or the output, said in one line."""


def matplotlib_or_exit(tool):
    """matplotlib on the Agg backend, labels as literal text (names come from the user's scenes)."""
    try:
        import matplotlib
    except ImportError:
        sys.exit(f"{tool}: error: matplotlib is missing: install python3-matplotlib (Debian)")
    matplotlib.use("Agg")
    matplotlib.rcParams["text.parse_math"] = False
    return matplotlib


def read_report(path, key, producer):
    """The JSON object in `path`, which must hold a list under `key` (what `producer` writes)."""
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except OSError as error:
        raise PlotError(f"{path}: {error.strerror}")
    except ValueError as error:
        raise PlotError(f"{path}: not valid JSON: {error}")
    if not isinstance(data, dict) or not isinstance(data.get(key), list):
        raise PlotError(f"{path}: no '{key}' array: not a {producer} file")
    return data


def save_svg(fig, path):
    """Writes the SVG through `path`.partial, renamed into place."""
    temporary = path + ".partial"
    try:
        fig.savefig(temporary, format="svg")
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def main(tool, description, default_json, key, producer, plot):
    """The scripts' command line (JSON [-o OUT]): reads the JSON, makes OUT (default: the JSON's
    folder) and calls plot(data, out); what can go wrong is one line on stderr and exit status 1."""
    import argparse
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("json", nargs="?" if default_json else None, default=default_json, help=f"{producer} output")
    parser.add_argument("-o", "--out", help="folder for the SVG files (default: the JSON's folder)")
    args = parser.parse_args()
    json_path = args.json
    try:
        data = read_report(json_path, key, producer)
        out = args.out or os.path.dirname(os.path.abspath(json_path))
        os.makedirs(out, exist_ok=True)
        plot(data, out)
    except PlotError as error:
        message = str(error)
    except KeyError as error:
        message = f"{json_path}: missing field {error}"
    except (IndexError, TypeError, ValueError) as error:
        message = f"{json_path}: unexpected data: {error}"
    except OSError as error:  # writing the charts
        message = f"{error.filename}: {error.strerror}" if error.filename else str(error)
    else:
        return 0
    print(f"{tool}: error: {message}", file=sys.stderr)
    return 1
