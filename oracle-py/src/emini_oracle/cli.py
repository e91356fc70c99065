"""The oracle's command line.

    emini-oracle run [--engine pymunk|box2d] [--out DIR] [--schema FILE] [--jobs N] PATHS...
        Runs scene files (folders: recursively) in pymunk (or Box2D v3 with --engine box2d); writes DIR/<scene id>.trace.json (trace
        format v1, source "pymunk") and DIR/oracle-results.json (one entry per file: status ok,
        skipped, unsupported, invalid or error; what pymunk cannot express; the trace's path).
    emini-oracle expand [--schema FILE] PATHS...
        Prints the scenes with generators expanded, as JSON (the harness's `expand` prints the same).
    emini-oracle serve [--engine pymunk|box2d] [--schema FILE]
        Runs scene variants sent as JSON lines on stdin, one response line each (trace, best step
        time over repeats): the harness's sweeps and stability maps use it (see serve.py).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from . import scene as scene_mod
from .run import run_file


def _loader(schema):
    return scene_mod.Loader(Path(schema) if schema else scene_mod.find_schema(Path.cwd()))


_worker_loader = None
_worker_engine = "pymunk"


def _init_worker(schema, engine="pymunk"):
    global _worker_loader, _worker_engine
    _worker_loader = _loader(schema)
    _worker_engine = engine


def _run_one(args):
    file, out = args
    return run_file(_worker_loader, file, Path(out), _worker_engine)


def cmd_run(args):
    t0 = time.perf_counter()
    schema = args.schema or str(scene_mod.find_schema(Path.cwd()))
    files = scene_mod.scene_files(args.paths)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    jobs = max(1, args.jobs or os.cpu_count() or 1)
    work = [(str(f), str(out)) for f in files]
    if jobs == 1 or len(work) <= 1:
        _init_worker(schema, args.engine)
        entries = []
        for w in work:
            entries.append(_run_one(w))
            _progress(entries[-1], args.quiet)
    else:
        # Longest scenes first would be better, but file order keeps the output stable.
        with ProcessPoolExecutor(jobs, initializer=_init_worker, initargs=(schema, args.engine)) as pool:
            entries = []
            for e in pool.map(_run_one, work):
                entries.append(e)
                _progress(e, args.quiet, args.engine)
    counts = {}
    for e in entries:
        counts[e["status"]] = counts.get(e["status"], 0) + 1
    doc = {"format": "emini-oracle-results", "version": 1, "source": args.engine,
           "seconds": round(time.perf_counter() - t0, 2), "counts": counts, "scenes": entries}
    with open(out / "oracle-results.json", "w", encoding="utf-8") as f:
        json.dump(doc, f, indent=1)
    summary = ", ".join(f"{n} {s}" for s, n in sorted(counts.items()))
    print(f"{len(entries)} scenes in {args.engine}: {summary} ({doc['seconds']} s)", file=sys.stderr if args.quiet else sys.stdout)
    bad = counts.get("error", 0) + counts.get("invalid", 0)
    return 1 if bad else 0


def _progress(e, quiet, engine="pymunk"):
    if quiet:
        return
    extra = ""
    if e["unsupported"]:
        extra = f"  {engine} cannot express: " + "; ".join(n["element"] for n in e["unsupported"])
    msg = f"  {e['message']}" if e["message"] and e["status"] != "ok" else ""
    print(f"{e['status']:<12}{e['scene'] or e['file']:<50}{e['seconds']:>8.2f} s{extra}{msg}", flush=True)


def cmd_expand(args):
    loader = _loader(args.schema)
    out = []
    bad = 0
    for f in scene_mod.scene_files(args.paths):
        try:
            out.append(loader.load(f).expanded_json())
        except scene_mod.SceneError as e:
            print(e, file=sys.stderr)
            bad += 1
    json.dump(out, sys.stdout, indent=1)
    print()
    return 1 if bad else 0


def cmd_serve(args):
    from .serve import serve
    return serve(_loader(args.schema), engine=args.engine)


def main(argv=None):
    p = argparse.ArgumentParser(prog="emini-oracle", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run", help="run scenes in pymunk and write traces")
    r.add_argument("paths", nargs="+", metavar="PATHS")
    r.add_argument("--out", default="reports/oracle", help="where traces go (default: reports/oracle)")
    r.add_argument("--schema", help="the scenario schema (default: scenarios/scenario.schema.json here or above)")
    r.add_argument("--jobs", type=int, help="scenes run in parallel (default: the number of cores)")
    r.add_argument("--quiet", action="store_true", help="only the summary line, on stderr")
    r.add_argument("--engine", choices=("pymunk", "box2d"), default="pymunk",
                   help="the oracle's engine: pymunk (default) or box2d (Box2D v3 through pyb2d3)")
    r.set_defaults(func=cmd_run)
    e = sub.add_parser("expand", help="print scenes with generators expanded, as JSON")
    e.add_argument("paths", nargs="+", metavar="PATHS")
    e.add_argument("--schema")
    e.set_defaults(func=cmd_expand)
    v = sub.add_parser("serve", help="run scene variants sent as JSON lines on stdin (the harness's sweeps)")
    v.add_argument("--schema")
    v.add_argument("--engine", choices=("pymunk", "box2d"), default="pymunk")
    v.set_defaults(func=cmd_serve)
    args = p.parse_args(argv)
    return args.func(args)


if __name__ == "__main__":
    raise SystemExit(main())
