"""The package's stubs (__init__.pyi) against the module: the same names and
keywords with the same defaults, and a docstring for every function help() shows."""

import ast
import inspect
import pathlib
import re

import lumibench as lb

STUB = pathlib.Path(lb.__file__).with_name("__init__.pyi")


def stub_functions():
    tree = ast.parse(STUB.read_text())
    out = {}
    nodes = list(tree.body)
    for c in tree.body:
        if isinstance(c, ast.ClassDef):
            nodes += [ast.FunctionDef(name=c.name + ".__init__", args=n.args) for n in c.body
                      if isinstance(n, ast.FunctionDef) and n.name == "__init__"]
    for node in nodes:
        if isinstance(node, ast.FunctionDef):
            a = node.args
            names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs if x.arg != "self"]
            defaults = {x.arg: ast.literal_eval(d) for x, d in zip(a.kwonlyargs, a.kw_defaults) if d is not None}
            pos_defaults = a.defaults
            for x, d in zip((a.posonlyargs + a.args)[len(a.args) - len(pos_defaults):], pos_defaults):
                defaults[x.arg] = ast.literal_eval(d)
            out[node.name] = (names, defaults)
    return out, {n.name for n in tree.body if isinstance(n, ast.ClassDef)}


def signature_of(f):
    """Keyword names and defaults of a Python function, or of a nanobind one from its __nb_signature__."""
    if inspect.isfunction(f):
        s = inspect.signature(f)
        return [p for p in s.parameters], {k: p.default for k, p in s.parameters.items()
                                           if p.default is not inspect.Parameter.empty}
    text, _, values = f.__nb_signature__[0]
    # nanobind writes the defaults as \\0, \\1, ... and gives their values apart
    text = re.sub(r"\\(\d+)", r"_d\1", text).replace("def ", "def f_", 1)
    args = ast.parse(text + ": pass").body[0].args

    def value(node):
        return values[int(node.id[2:])] if isinstance(node, ast.Name) else ast.literal_eval(node)

    names = [x.arg for x in args.posonlyargs + args.args + args.kwonlyargs if x.arg != "self"]
    defaults = {x.arg: value(d) for x, d in zip(args.kwonlyargs, args.kw_defaults) if d is not None}
    for x, d in zip(args.args[len(args.args) - len(args.defaults):], args.defaults):
        defaults[x.arg] = value(d)
    return names, defaults


def test_stubs_match_the_module():
    funcs, classes = stub_functions()
    assert {n for n in funcs if "." not in n} | classes == set(lb.__all__)
    assert "Scene.__init__" in funcs
    for name, (names, defaults) in funcs.items():
        obj = lb
        for part in name.split("."):
            obj = getattr(obj, part)
        got_names, got_defaults = signature_of(obj)
        assert got_names == names, name
        assert got_defaults == defaults, name


def test_every_public_name_has_a_docstring():
    for name in lb.__all__:
        doc = getattr(lb, name).__doc__
        assert doc and len(doc) > 40, name
