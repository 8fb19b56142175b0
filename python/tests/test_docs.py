"""Docs: docstrings on everything public, the examples in them run, and
the typing files ship with the package."""

import doctest
import pathlib
import pydoc

import ke_friction as kf


def test_everything_public_is_documented():
    assert kf.__doc__ and len(kf.__doc__) > 200
    for name in kf.__all__:
        obj = getattr(kf, name)
        if callable(obj):
            assert obj.__doc__ and len(obj.__doc__) > 40, name
    for cls in [kf.Table, kf.Curve, kf.Model, kf.Contact, kf.HeightDistribution, kf.Surface, kf.Container,
                kf.FrictionLaw]:
        for attr, value in vars(cls).items():
            if not attr.startswith("_"):
                doc = getattr(value, "__doc__", None) or getattr(getattr(value, "__func__", None), "__doc__", None)
                assert doc and len(doc) > 20, f"{cls.__name__}.{attr}"


def test_help_on_table_mu_explains_arguments_results_and_errors():
    text = pydoc.render_doc(kf.Table.mu, renderer=pydoc.plaintext)
    for word in ["psi", "theta", "f_star", "out_of_domain", "broadcast", "ValueError", "TypeError", "GIL",
                 "tolerance", "Examples"]:
        assert word in text, word


def test_the_examples_in_the_docstrings_run():
    result = doctest.testmod(kf, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 5 and result.failed == 0, result


def test_stubs_and_py_typed_ship_with_the_package():
    pkg = pathlib.Path(kf.__file__).parent
    assert (pkg / "py.typed").exists() and (pkg / "_core.pyi").exists()
    stub = (pkg / "_core.pyi").read_text()
    for name in ["class TableCore", "class CurveCore", "class ModelCore", "class DistributionCore",
                 "class FrictionLawCore", "class ContainerCore", "def params_from_physical"]:
        assert name in stub, name


def test_the_dask_example_states_its_requirements():
    """The Dask example's extra packages are written down where a user
    looks: its module docstring and the README."""
    root = pathlib.Path(__file__).resolve().parents[2]
    example = (root / "python" / "examples" / "dask_friction_map.py").read_text()
    docstring = example.split('"""')[1]
    assert 'pip install "dask[array,distributed]"' in docstring
    assert 'pip install "dask[array,distributed]"' in (root / "README.md").read_text()
