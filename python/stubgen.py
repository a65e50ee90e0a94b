"""stubgen.py MODULE OUT.pyi — type stubs for a pybind11 module, from the module itself.

Run at build time on rtamp._rtamp (python/CMakeLists.txt, with python3 -P so that
the source tree's python/rtamp does not shadow the built package; Debian has no
pybind11-stubgen). Every public name of the module gets a stub: classes with
their methods, properties, static methods and enum members; functions with the
signatures pybind11 writes on the first line(s) of each docstring (one
@overload per signature of an overloaded function). Types are rewritten to
names the stub can resolve (this module's classes unqualified, typing's
generics imported); a default value Python cannot read becomes `...`.
Invariant: the output parses with ast and names every public attribute; a
signature that would not parse is written as (*args, **kwargs) -> Any and
reported on stderr (the build still succeeds; for a module-level function
python/tests/test_stubs.py then fails).
"""

import ast
import importlib
import inspect
import re
import sys

TYPING = ["Any", "Callable", "Dict", "Iterable", "Iterator", "List", "Optional", "Sequence", "Set",
          "Tuple", "Union", "overload"]
# pybind11 type names with no Python counterpart a stub can name.
RENAMES = {"handle": "Any", "capsule": "Any", "numpy.ndarray": "Any", "buffer": "Any", "function": "Callable[..., Any]", "iterator": "Iterator[Any]",
           "FrozenSet": "frozenset", "json": "Any"}


def signatures(name, doc):
    """The pybind11 signature lines `name(...) -> ret` at the start of a docstring."""
    if not doc:
        return []
    lines = doc.splitlines()
    if lines and lines[0].strip() == "Overloaded function.":
        pattern = re.compile(rf"^\d+\. {re.escape(name)}(\(.*\)(?: -> .*)?)$")
        return [m.group(1) for m in map(pattern.match, lines) if m]
    m = re.match(rf"^{re.escape(name)}(\(.*\)(?: -> .*)?)$", lines[0]) if lines else None
    return [m.group(1)] if m else []


def clean(sig, module):
    """A pybind11 signature `(a: T = default, ...) -> R` rewritten for a stub."""
    sig = sig.replace(module + ".", "")
    sig = re.sub(r"\b(pybind11_builtins|typing)\.", "", sig)
    sig = re.sub(r"\b(?:\w+::)+(\w+)", r"\1", sig)  # a C++ name pybind11 could not map: its last part
    sig = re.sub(r"numpy\.ndarray\[(?:[^\[\]]|\[[^\[\]]*\])*\]", "Any", sig)  # arrays: dtype and shape dropped
    for k, v in RENAMES.items():  # in type positions only (a parameter name is followed by ':')
        sig = re.sub(rf"(?<![\w.*]){re.escape(k)}(?![\w.:])", v, sig)
    # Defaults: `= <...>` reprs and anything else that is not a literal become `...`.
    sig = re.sub(r"= <[^>]*>", "= ...", sig)
    return sig


def valid(sig):
    try:
        ast.parse(f"def f{sig}: ...")
        return True
    except SyntaxError:
        return False


def literal_defaults(sig):
    """Replaces defaults that are not Python literals by `...`, parameter by parameter."""
    tree = ast.parse(f"def f{sig}: ...").body[0]
    args = tree.args
    for defaults in (args.defaults, args.kw_defaults):
        for i, d in enumerate(defaults):
            if d is None:
                continue
            try:
                ast.literal_eval(d)
            except ValueError:
                defaults[i] = ast.Constant(value=...)
    text = ast.unparse(tree)  # "def f(...) -> R:\n    ..."
    return text[len("def f"):text.rindex(":")]


def function_stub(name, obj, module, indent, errors, decorator=None):
    out = []
    sigs = signatures(name, getattr(obj, "__doc__", None))
    if not sigs:
        sigs = ["(*args, **kwargs) -> Any"]
        errors.append(f"{indent}{name}: no signature in its docstring")
    for s in sigs:
        s = clean(s, module)
        if not valid(s):
            errors.append(f"{name}{s}: does not parse")
            s = "(*args, **kwargs) -> Any"
        s = literal_defaults(s)
        if len(sigs) > 1:
            out.append(f"{indent}@overload")
        if decorator:
            out.append(f"{indent}@{decorator}")
        out.append(f"{indent}def {name}{s}: ...")
    return out


def class_stub(name, cls, module, errors):
    bases = [b.__name__ for b in cls.__bases__ if b.__module__ == module]
    if issubclass(cls, BaseException):
        bases = [b.__name__ for b in cls.__bases__]
    out = [f"class {name}({', '.join(bases)}):" if bases else f"class {name}:"]
    body = []
    members = getattr(cls, "__members__", None)
    if isinstance(members, dict):  # a pybind11 enum
        body += [f"    {m}: {name}" for m in members]
    for attr, value in sorted(cls.__dict__.items()):
        if attr.startswith("_") and attr not in ("__init__", "__call__", "__iter__", "__len__", "__getitem__",
                                                   "__eq__", "__hash__", "__contains__", "__enter__", "__exit__"):
            continue
        if isinstance(members, dict) and attr in members:
            continue
        if isinstance(value, property):
            ret = "Any"
            if value.fget is not None:
                sig = signatures("", value.fget.__doc__ or "")
                m = re.match(r"^\(.*\) -> (.*)$", sig[0]) if sig else None
                if m:
                    ret = clean(m.group(1), module)
                    if not valid(f"(x: {ret})"):
                        ret = "Any"
            body.append(f"    @property")
            body.append(f"    def {attr}(self) -> {ret}: ...")
            if value.fset is not None:
                body.append(f"    @{attr}.setter")
                body.append(f"    def {attr}(self, value: {ret}) -> None: ...")
        elif isinstance(value, staticmethod):
            body += function_stub(attr, value.__func__, module, "    ", errors, "staticmethod")
        elif callable(value) and type(value).__name__ in ("instancemethod", "builtin_function_or_method",
                                                         "function", "method_descriptor"):
            body += function_stub(attr, value, module, "    ", errors)
        elif attr == "__hash__" and value is None:
            continue
        elif not callable(value) and not attr.startswith("_"):
            body.append(f"    {attr}: {type(value).__name__ if type(value).__module__ == 'builtins' else 'Any'}")
    return out + (body or ["    ..."])


def generate(module_name):
    mod = importlib.import_module(module_name)
    errors = []
    out = [f'"""Type stubs of {module_name}, generated from the module by python/stubgen.py."""', "",
           f"from typing import {', '.join(TYPING)}", ""]
    names = sorted(n for n in dir(mod) if not n.startswith("_"))
    classes = [n for n in names if inspect.isclass(getattr(mod, n))]
    # Base classes first, so that the stub reads top-down.
    ordered = []
    def visit(n):
        if n in ordered:
            return
        for b in getattr(mod, n).__bases__:
            if b.__name__ in classes and b.__module__ == module_name:
                visit(b.__name__)
        ordered.append(n)
    for n in classes:
        visit(n)
    for n in ordered:
        out += class_stub(n, getattr(mod, n), module_name, errors) + [""]
    for n in names:
        obj = getattr(mod, n)
        if n in classes:
            continue
        if callable(obj):
            out += function_stub(n, obj, module_name, "", errors)
        else:
            out.append(f"{n}: {type(obj).__name__}")
    out.append("__version__: str")
    text = "\n".join(out) + "\n"
    ast.parse(text)
    return text, errors


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: stubgen.py MODULE OUT.pyi\n")
        return 2
    text, errors = generate(argv[1])
    for e in errors:
        sys.stderr.write(f"stubgen: {argv[1]}: {e}\n")
    with open(argv[2], "w") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
