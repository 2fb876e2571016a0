#!/usr/bin/env python3
"""The framework's layers go one way (docs/framework.md, "Layers").

Each area of framework/ (include/stoa/AREA/ and src/AREA/) sits in a layer;
a file may include the headers of its own layer and of the layers below it,
never of a layer above. No framework file reaches outside framework/ with a
relative include ("../"), and none names labs/, solutions/ or autograder/.

stoa_core, the GL-free library the grader links, is one list of sources in
framework/CMakeLists.txt (the areas of layers 0-2 and a few GL-free files of
higher areas: manifests, GLSL expansion, asset and scene data). None of them
may reach OpenGL: no file they include, directly or through stoa headers,
includes GL, EGL, GLEW, GLUT or OSMesa.

    check_layers.py [FRAMEWORK_DIR]      exit 0: the layers hold; 1: what breaks them
"""
import pathlib
import re
import sys

# Lowest first. The GL-free layers come first; OpenGL starts at gl.
LAYERS = [
    ["core", "platform"],              # errors, paths, the student-code table; POSIX or Windows
    ["image", "geometry", "audio"],    # images and their comparison, CPU meshes, sound clips
    ["crowd"],                         # crowds as data and their simulation
    ["gl"],                            # OpenGL wrapped
    ["app", "assets"],                 # windows, contexts, input; assets by name
    ["camera"],                        # the cameras
    ["scene"],                         # objects, lights, draw lists
    ["render"],                        # the renderers and their passes
    ["editor"],                        # the scene editor's data and assets
    ["lab"],                           # the lab shell: runLab(), the window, manifests
]
RANK = {area: rank for rank, areas in enumerate(LAYERS) for area in areas}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')


def area_of(path, root):
    parts = path.relative_to(root).parts
    if parts[0] == "include" and len(parts) > 3 and parts[1] == "stoa":
        return parts[2]
    if parts[0] == "src" and len(parts) > 2:
        return parts[1]
    return None


def problems(root):
    found = []
    for path in sorted(root.rglob("*")):
        if path.suffix not in (".hpp", ".cpp", ".h") or not path.is_file():
            continue
        area = area_of(path, root)
        if area is None:
            continue
        if area not in RANK:
            found.append(f"{path}: the area '{area}' is in no layer of tests/framework/check_layers.py")
            continue
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            name = match.group(2)
            where = f"{path}:{number}"
            if "../" in name or re.match(r"(labs|solutions|autograder)/", name):
                found.append(f"{where}: includes \"{name}\": the framework includes nothing outside framework/")
                continue
            target = re.match(r"stoa/(\w+)/", name)
            if not target:
                continue
            other = target.group(1)
            if other not in RANK:
                found.append(f"{where}: includes <{name}>, whose area '{other}' is in no layer")
            elif RANK[other] > RANK[area]:
                found.append(f"{where}: {area} (layer {RANK[area]}) includes <{name}> of {other} "
                             f"(layer {RANK[other]}, above it): the framework's layers go one way "
                             f"(docs/framework.md, \"Layers\")")
    return found


GL_HEADER = re.compile(r"^(GL|EGL|GLES\d*)/|^(glew|glut|osmesa)\.h$", re.IGNORECASE)


def core_sources(root):
    """The sources of `target_sources(stoa_core PRIVATE ...)` in framework/CMakeLists.txt."""
    text = "\n".join(line.split("#")[0] for line in (root / "CMakeLists.txt").read_text().splitlines())
    sources = []
    for block in re.findall(r"target_sources\(stoa_core\s+PRIVATE(.*?)\)", text, re.S):
        sources += [word for word in block.split() if word.endswith(".cpp")]
    return [root / source for source in sources]


def gl_reached(root):
    """Each stoa_core source that reaches an OpenGL header, with the chain of includes."""
    found = []
    for source in core_sources(root):
        if not source.is_file():
            found.append(f"{source}: listed for stoa_core in {root / 'CMakeLists.txt'} but missing")
            continue
        seen, stack = set(), [(source, [source.name])]
        while stack:
            path, chain = stack.pop()
            if path in seen:
                continue
            seen.add(path)
            for line in path.read_text(errors="replace").splitlines():
                match = INCLUDE.match(line)
                if not match:
                    continue
                name = match.group(2)
                if GL_HEADER.match(name):
                    found.append(f"{source}: stoa_core reaches OpenGL: {' -> '.join(chain + [name])} "
                                 f"(the GL-free library; docs/framework.md, \"Two libraries\")")
                    stack.clear()
                    break
                header = root / "include" / name if name.startswith("stoa/") else path.parent / name
                if header.is_file():
                    stack.append((header, chain + [name]))
    return found


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2] / "framework")
    if not (root / "include" / "stoa").is_dir():
        print(f"check_layers: {root} is not the framework folder (no include/stoa/)", file=sys.stderr)
        return 2
    found = problems(root) + gl_reached(root)
    for problem in found:
        print(problem)
    if found:
        print(f"check_layers: {len(found)} include(s) break the layers")
        return 1
    print(f"check_layers: {sum(len(a) for a in LAYERS)} areas in {len(LAYERS)} layers, every include goes down; "
          f"the {len(core_sources(root))} sources of stoa_core reach no OpenGL header")
    return 0


if __name__ == "__main__":
    sys.exit(main())
