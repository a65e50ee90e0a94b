"""Every public part of the rtamp module has a docstring of its own (issue 12: "docstrings everywhere").

Walks the package (the C++ extension and its Python submodules): every public class,
function, method, static method and property must carry text beyond pybind11's generated
signature line. Names starting with "_" are not public; enum members are values, not API.
"""

import inspect
import re
import types

import rtamp


def _own_text(name, doc):
    """The docstring with pybind11's signature lines ("name(args) -> ret", "Overloaded
    function.", "1. name(...)") removed."""
    if not doc:
        return ""
    sig = re.compile(r"^\s*(\d+\.\s+)?(" + re.escape(name) + r")?\(.*\)(\s*->\s*.*)?\s*$")
    kept = [line for line in doc.splitlines() if not sig.match(line) and line.strip() != "Overloaded function."]
    return "\n".join(kept).strip()


def _is_enum_class(cls):
    return hasattr(cls, "__members__") and isinstance(getattr(cls, "__members__"), dict)


def _missing():
    """(qualified name, kind) of every public part without a docstring of its own."""
    missing, seen = [], set()

    def check_callable(qual, name, obj, kind):
        if not _own_text(name, getattr(obj, "__doc__", None)):
            missing.append((qual, kind))

    def walk_class(qual, cls):
        if id(cls) in seen:
            return
        seen.add(id(cls))
        if not _own_text(cls.__name__, cls.__doc__):
            missing.append((qual, "class"))
        enum = _is_enum_class(cls)
        for name, member in vars(cls).items():
            if name.startswith("_"):
                continue
            if enum and name in cls.__members__:
                continue
            if enum and name in ("name", "value"):  # pybind11's own enum accessors
                continue
            q = f"{qual}.{name}"
            if isinstance(member, property):
                if not _own_text(name, member.__doc__):
                    missing.append((q, "property"))
            elif isinstance(member, (staticmethod, classmethod)):
                check_callable(q, name, member.__func__, "static method")
            elif callable(member):
                check_callable(q, name, member, "method")

    def walk_module(mod):
        if id(mod) in seen:
            return
        seen.add(id(mod))
        if not (mod.__doc__ or "").strip():
            missing.append((mod.__name__, "module"))
        for name in dir(mod):
            if name.startswith("_"):
                continue
            obj = getattr(mod, name)
            qual = f"{mod.__name__}.{name}"
            if isinstance(obj, types.ModuleType):
                if obj.__name__.startswith("rtamp"):
                    walk_module(obj)
            elif inspect.isclass(obj):
                if (obj.__module__ or "").startswith("rtamp"):
                    walk_class(qual, obj)
            elif callable(obj) and (getattr(obj, "__module__", "") or "").startswith("rtamp"):
                check_callable(qual, name, obj, "function")

    walk_module(rtamp)
    return missing, seen


def test_every_public_part_has_a_docstring():
    missing, seen = _missing()
    assert len(seen) > 30  # the walk reached the module's classes
    assert not missing, f"{len(missing)} without a docstring:\n" + "\n".join(f"  {q} ({k})" for q, k in missing)


def test_the_walk_sees_what_it_checks():
    # The checker itself: pybind11's bare signature is not a docstring, text after it is.
    assert _own_text("f", "f(self: X) -> int\n") == ""
    assert _own_text("p", "(self: X) -> int\n") == ""  # a property getter's bare signature
    assert _own_text("f", "f(self: X) -> int\n\nThe count.\n") == "The count."
    assert _own_text("f", "Overloaded function.\n\n1. f(x: int) -> None\n\n2. f(x: str) -> None\n") == ""
