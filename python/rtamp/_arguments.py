"""Pythonic TypeErrors for calls into the compiled core.

pybind11 answers a call whose argument types match no signature with
"incompatible function arguments. The following argument types are
supported: ..." and the whole signature. For the module's functions, its
classes' constructors, static methods and methods this names the argument instead:
"load_scenario(): argument 'path_or_builtin' must be str, not int", with
pybind11's text kept below it. Only a definite mismatch against a single
signature is renamed (builtin types and the module's own classes); anything
else (overloads, container types) keeps pybind11's message unchanged.
The methods of classes Python code overrides (World, EpisodeObserver,
CostModel and their subclasses) get their wrapper as a compiled method
(_rtamp._as_method): pybind11 finds an override by looking for a method that
is not its own, and would take a Python wrapper for one.
"""

import functools

_INCOMPATIBLE = ("incompatible function arguments", "incompatible constructor arguments")


def _split_top_level(text):
    """Split a parameter list at the commas outside brackets and quotes."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            if c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:].strip())
    return parts


def _parameters(doc):
    """(positional names, keyword-only names, name -> type) of a one-signature docstring, or None."""
    if not doc:
        return None
    first = doc.splitlines()[0]
    if "(*args, **kwargs)" in first or "(" not in first:
        return None
    inner = first[first.index("(") + 1:first.rindex(")")] if ")" in first else ""
    positional, keyword_only, types, star = [], [], {}, False
    for p in _split_top_level(inner):
        if p == "*":
            star = True
            continue
        name, _, rest = p.partition(":")
        name = name.strip()
        types[name] = rest.split("=")[0].strip() if "=" in rest else rest.strip()
        (keyword_only if star else positional).append(name)
    if positional and positional[0] == "self":
        positional = positional[1:]
    return positional, keyword_only, types


def _accepts(type_name, value, core):
    """True / False when pybind11 would (not) convert `value` to the type, None when this cannot tell."""
    if type_name == "object":
        return True
    if type_name == "str":
        return isinstance(value, (str, bytes))
    if type_name == "float":
        return hasattr(value, "__float__") or hasattr(value, "__index__")
    if type_name == "int":
        return not isinstance(value, float) and (hasattr(value, "__index__") or hasattr(value, "__int__"))
    if type_name == "bool":  # pybind11 converts any number and None to bool
        return False if isinstance(value, (str, bytes, list, tuple, dict)) else None
    if type_name.startswith(core.__name__ + "."):
        cls = getattr(core, type_name[len(core.__name__) + 1:], None)
        return isinstance(value, cls) if isinstance(cls, type) else None
    return None


def _renamed(what, doc, args, kwargs, core, error):
    """The TypeError naming the argument, or None when it cannot be told."""
    params = _parameters(doc)
    if params is None:
        return None
    positional, keyword_only, types = params
    if len(args) > len(positional):
        return TypeError(f"{what}(): takes {len(positional)} positional argument"
                         f"{'' if len(positional) == 1 else 's'} but {len(args)} were given\n{error}")
    given = dict(zip(positional, args))
    for name, value in kwargs.items():
        if name not in types or name == "self":
            return TypeError(f"{what}(): unexpected keyword argument '{name}'\n{error}")
        given[name] = value
    for name, value in given.items():
        expected = types[name]
        if _accepts(expected, value, core) is False:
            shown = expected[len(core.__name__) + 1:] if expected.startswith(core.__name__ + ".") else expected
            return TypeError(f"{what}(): argument '{name}' must be {shown}, not {type(value).__name__}\n{error}")
    return None


def _better(error, shown, doc, args, kwargs, core):
    """The renamed TypeError for pybind11's `error`, or None to keep it."""
    text = str(error)
    if not any(s in text for s in _INCOMPATIBLE):
        return None
    return _renamed(shown, doc, args, kwargs, core, text)


def _wrap(function, shown, skip, core):
    """`function` raising the renamed TypeError; `shown`: its name in messages; `skip`: leading args not in
    the signature's list (the instance of a constructor)."""
    doc = function.__doc__

    @functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as e:
            better = _better(e, shown, doc, args[skip:], kwargs, core)
            if better is None:
                raise
            raise better from None
    if skip == 0 and "." not in shown:  # pickled by reference as rtamp.NAME (Dask ships functions so)
        call.__module__, call.__qualname__ = "rtamp", shown
    return call


def _wrap_overridable(function, shown, attr, core):
    """A method of a class Python overrides, wrapped like _wrap. pybind11 takes a call made from a
    frame named after the method whose first argument is the instance for `super().attr()` from an
    override (and then runs the C++ method, not the override again): this wrapper is such a frame."""
    doc = function.__doc__

    def method(self, *args, **kwargs):
        try:
            return function(self, *args, **kwargs)
        except TypeError as e:
            better = _better(e, shown, doc, args, kwargs, core)
            if better is None:
                raise
            raise better from None
    method.__code__ = method.__code__.replace(co_name=attr)
    return method


def name_arguments(namespace, core):
    """Wrap the core's functions in `namespace` and its classes' constructors and methods."""
    overridden = tuple(getattr(core, n) for n in ("World", "EpisodeObserver", "CostModel") if hasattr(core, n))
    for name, value in list(namespace.items()):
        if name.startswith("_") or getattr(value, "__module__", None) != core.__name__:
            continue
        if type(value).__name__ == "builtin_function_or_method":
            namespace[name] = _wrap(value, name, 0, core)
        elif isinstance(value, type):
            for attr, member in list(vars(value).items()):
                kind = type(member).__name__
                if attr == "__init__" and kind == "instancemethod":
                    value.__init__ = _wrap(member, name, 1, core)
                elif attr.startswith("_"):
                    continue
                elif kind == "instancemethod" and issubclass(value, overridden):
                    wrapper = _wrap_overridable(member, f"{name}.{attr}", attr, core)
                    setattr(value, attr, core._as_method(value, attr, wrapper, member.__doc__ or ""))
                elif kind == "instancemethod":
                    setattr(value, attr, _wrap(member, f"{name}.{attr}", 1, core))
                elif kind == "staticmethod":
                    setattr(value, attr, staticmethod(_wrap(member.__func__, f"{name}.{attr}", 0, core)))
