"""Reads CSV files as a user's tools read them, and fails when one is misread (issue 32).

Usage: csv_check.py READER FILE[:COLUMN[:COLUMN...]]...
READER is csv (Python's csv module), pandas (pandas.read_csv with its defaults; exit 77, ctest's
skip code, when pandas is not installed) or sqlite (the sqlite3 command's .import into a table it
makes from the header). For every file: the first row is the header (no line starts with '#'),
every row has the header's number of fields, the names are unique and not empty, and a missing
value is an empty field (never nan, inf, n/a, NULL or a dash); each COLUMN named must be there and
hold at least one number, read as a number by the reader. Prints one line per file and
"N passed, N failed".
"""
import csv
import math
import subprocess
import sys
import tempfile

MISSING_SPELLINGS = {"nan", "-nan", "inf", "-inf", "+inf", "n/a", "na", "null", "none", "-", "\u2013", "?"}


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def read_plain(path):
    """Header and rows with the csv module, checked as RFC 4180 footsim writes it."""
    with open(path, newline="", encoding="utf-8") as f:
        text = f.read()
    problems = []
    if any(line.startswith("#") for line in text.splitlines()):
        problems.append("a line starts with '#'")
    rows = list(csv.reader(text.splitlines(True)))
    if not rows:
        return None, [], ["no header row"]
    header, body = rows[0], rows[1:]
    if len(set(header)) != len(header) or any(not h for h in header):
        problems.append("header names not unique or empty: %r" % header)
    for i, r in enumerate(body, start=2):
        if len(r) != len(header):
            problems.append("row %d has %d fields, the header %d" % (i, len(r), len(header)))
            break
        bad = [v for v in r if v.strip().lower() in MISSING_SPELLINGS]
        if bad:
            problems.append("row %d spells a missing value %r (an empty field is the only spelling)" % (i, bad[0]))
            break
    return header, body, problems


def numeric_columns(header, body):
    """The columns whose every non-empty field is a finite number, and that have one."""
    cols = []
    for j, name in enumerate(header):
        values = [r[j] for r in body if j < len(r) and r[j] != ""]
        nums = [number(v) for v in values]
        if values and all(n is not None and math.isfinite(n) for n in nums):
            cols.append(name)
    return cols


def check_pandas(path, header, body, columns):
    import pandas  # noqa: imported here: the caller skips when it is missing
    frame = pandas.read_csv(path)
    problems = []
    if list(frame.columns) != header:
        problems.append("pandas read columns %r, the header has %r" % (list(frame.columns)[:5], header[:5]))
        return problems
    if len(frame) != len(body):
        problems.append("pandas read %d rows, the file has %d" % (len(frame), len(body)))
    for name in numeric_columns(header, body):
        if not pandas.api.types.is_numeric_dtype(frame[name]):
            problems.append("pandas read column %s as %s, not numbers" % (name, frame[name].dtype))
    for name in columns:
        if name in frame.columns and not pandas.api.types.is_numeric_dtype(frame[name]):
            problems.append("pandas: column %s is not numeric" % name)
    return problems


def check_sqlite(path, header, body, columns):
    problems = []
    with tempfile.TemporaryDirectory() as tmp:
        db = tmp + "/t.sqlite"
        script = ".import --csv '%s' t\n" % path.replace("'", "''")
        run = subprocess.run(["sqlite3", db], input=script, text=True, capture_output=True)
        if run.returncode != 0 or run.stderr:
            return ["sqlite3 .import failed: " + run.stderr.strip()]
        names = subprocess.run(["sqlite3", db, "SELECT name FROM pragma_table_info('t') ORDER BY cid"],
                               text=True, capture_output=True).stdout.splitlines()
        if names != header:
            problems.append("sqlite3 made columns %r, the header has %r" % (names[:5], header[:5]))
        count = subprocess.run(["sqlite3", db, "SELECT count(*) FROM t"], text=True, capture_output=True).stdout.strip()
        if count != str(len(body)):
            problems.append("sqlite3 read %s rows, the file has %d" % (count, len(body)))
        for name in columns:
            q = 'SELECT max(CAST("%s" AS REAL)) FROM t WHERE "%s" <> \'\'' % (name, name)
            got = subprocess.run(["sqlite3", db, q], text=True, capture_output=True).stdout.strip()
            j = header.index(name) if name in header else -1
            want = max(number(r[j]) for r in body if r[j] != "") if j >= 0 else None
            if number(got) is None or want is None or not math.isclose(number(got), want, rel_tol=1e-12):
                problems.append("sqlite3: max(%s) is %r, the file's %r" % (name, got, want))
    return problems


def main(argv):
    if len(argv) < 3 or argv[1] not in ("csv", "pandas", "sqlite"):
        print(__doc__, file=sys.stderr)
        return 2
    reader = argv[1]
    if reader == "pandas":
        try:
            import pandas  # noqa: F401
        except ImportError:
            print("pandas is not installed (Debian: python3-pandas): skipped")
            return 77
    passed = failed = 0
    for spec in argv[2:]:
        path, *columns = spec.split(":")
        header, body, problems = read_plain(path)
        if header is not None:
            for name in columns:
                j = header.index(name) if name in header else -1
                if j < 0 or not any(number(r[j]) is not None for r in body if j < len(r) and r[j] != ""):
                    problems.append("no column %s with a number" % name)
            if not problems and reader == "pandas":
                problems += check_pandas(path, header, body, columns)
            if not problems and reader == "sqlite":
                problems += check_sqlite(path, header, body, columns)
        if problems:
            failed += 1
            print("FAIL: %s (%s): %s" % (path, reader, "; ".join(problems)))
        else:
            passed += 1
            print("ok: %s (%s): %d columns, %d rows" % (path, reader, len(header), len(body)))
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
