#!/usr/bin/env python3
"""The layering of docs/architecture.md ("Layout"), enforced: run by scripts/test.sh.

Reads the module table of docs/architecture.md (each framework module and the modules it
links) and the sentence on baselines/, then checks every #include "<module>/..." of
framework/ and baselines/ against them: a module includes itself and the modules it links,
directly or through their own links; `experiment` may include every framework module;
`baselines` what its sentence lists; nothing in framework/ includes baselines/. Third-party
headers stay where the same section puts them: CGAL in geometry and topology .cpp files (and
geometry/cgal_internal.h, which only .cpp files include), Box2D in sim .cpp files, yaml-cpp in
scenario (.cpp files and scenario/yaml_internal.h), oneTBB in experiment .cpp files, OMPL in
baselines .cpp files, nlohmann-json in experiment and baselines .cpp files; no *_internal.h is
included from a header. Prints each offending
file:line and exits 1 when there is one.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOC = ROOT / "docs" / "architecture.md"

# Third-party include prefix -> (module folder, also allowed in these headers).
THIRD_PARTY = {
    "CGAL/": (("framework/geometry", "framework/topology"), ("framework/geometry/cgal_internal.h",)),
    "box2d/": (("framework/sim",), ()),
    "yaml-cpp/": (("framework/scenario",), ("framework/scenario/yaml_internal.h",)),
    "tbb/": (("framework/experiment",), ()),
    "oneapi/tbb": (("framework/experiment",), ()),
    "ompl/": (("baselines",), ()),
    "nlohmann/": (("framework/experiment", "baselines"), ("framework/experiment/json_internal.h",)),
}


def module_links():
    """{module: set of modules it links} from the docs table."""
    text = DOC.read_text()
    rows = dict(re.findall(r"^\| `([a-z_]+)/` \|[^|]*\| ([^|]*)\|\s*$", text, re.M))
    modules = list(rows)
    links = {}
    for m, row in rows.items():
        if "everything in `framework/`" in row:
            links[m] = set(modules)
            continue
        head = row.split(";")[0]
        links[m] = {w for w in re.findall(r"[a-z_]+", head) if w in modules}
    sentence = re.search(r"`baselines/` links ([^(]*)\(", text)
    if not sentence:
        sys.exit("check_layering.py: docs/architecture.md has no sentence '`baselines/` links ...('")
    links["baselines"] = {w for w in re.findall(r"[a-z_]+", sentence.group(1)) if w in modules}
    return links


def module_of(path):
    rel = path.relative_to(ROOT).as_posix()
    if rel.startswith("framework/"):
        return rel.split("/")[1]
    if rel.startswith("baselines/"):
        return "baselines"
    return None


def main():
    links = module_links()
    bad = []
    files = sorted(list((ROOT / "framework").rglob("*.[ch]*")) + list((ROOT / "baselines").glob("*.[ch]*")))
    for path in files:
        if path.suffix not in (".h", ".cpp"):
            continue
        m = module_of(path)
        rel = path.relative_to(ROOT).as_posix()
        for n, line in enumerate(path.read_text().splitlines(), 1):
            q = re.match(r'\s*#\s*include\s+"([a-z_]+)/([^"]+)"', line)
            if q:
                dep, header = q.group(1), q.group(2)
                if dep != m and dep not in links.get(m, set()):
                    bad.append(f"{rel}:{n}: module {m} includes {dep}/{header}, which "
                               f"docs/architecture.md does not let it link")
                if path.suffix == ".h" and header.endswith("_internal.h"):
                    bad.append(f"{rel}:{n}: a header includes {dep}/{header} (internal headers "
                               f"are for .cpp files)")
            a = re.match(r"\s*#\s*include\s+<([^>]+)>", line)
            if a:
                for prefix, (homes, headers) in THIRD_PARTY.items():
                    if not a.group(1).startswith(prefix):
                        continue
                    home = any(rel.startswith(h + "/") for h in homes)
                    if not home or (path.suffix == ".h" and rel not in headers):
                        bad.append(f"{rel}:{n}: <{a.group(1)}> outside its module's .cpp files")
    for b in bad:
        print(b, file=sys.stderr)
    if bad:
        print("check_layering.py: includes that docs/architecture.md forbids (above)", file=sys.stderr)
        return 1
    print(f"check_layering.py: {len(files)} files of framework/ and baselines/ within the layering")
    return 0


if __name__ == "__main__":
    sys.exit(main())
