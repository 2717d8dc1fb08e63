"""fogdrift.fleet on Dask: one model per campaign on a LocalCluster of worker processes, byte for
byte the models of a serial run, with a refused unit reported and the others trained."""
import json

import pytest

import fogdrift
from fogdrift.fleet import train_fleet

distributed = pytest.importorskip("distributed")


@pytest.fixture(scope="module")
def units(tmp_path_factory):
    """Three units' campaigns (different instruments: different seeds) and a broken one."""
    d = tmp_path_factory.mktemp("fleet")
    paths = []
    for seed in (1, 2, 3):
        paths.append(d / f"unit{seed}")
        fogdrift.simulate("calibration", out=paths[-1], seed=seed, temps_degc=[-20, 10, 40],
                          repetitions=2)
    broken = d / "unit4"
    fogdrift.simulate("calibration", out=broken, seed=4, temps_degc=[-20, 10, 40], repetitions=2)
    manifest = json.loads((broken / "campaign.json").read_text())
    (broken / manifest["recordings"][0]["file"]).write_text("time_s,gyro_dph\n0,1\n")
    return paths, broken


def test_a_local_cluster_trains_the_serial_runs_models(units, tmp_path):
    paths, broken = units
    options = dict(method="ssa-svr", population=6, iterations=2, seed=7)
    serial = train_fleet(paths, **options)
    seen = []
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        parallel = train_fleet(paths + [broken], client=client, out=tmp_path / "models",
                               progress=lambda done, total, r: seen.append((done, total)),
                               **options)
    assert sorted(seen) == [(1, 4), (2, 4), (3, 4), (4, 4)]
    assert [r["campaign"] for r in parallel] == [str(p) for p in paths + [broken]]
    for s, p in zip(serial, parallel):
        assert s["error"] is None and p["error"] is None
        assert p["model"].to_json() == s["model"].to_json()
        assert p["evaluation"] == s["evaluation"]
        assert p["summary"]["hyperparameters"] == s["summary"]["hyperparameters"]
        written = tmp_path / "models" / (p["campaign"].rsplit("/", 1)[-1] + ".json")
        assert written.read_text() == s["model"].to_json()
    # The units differ: each model is its own instrument's.
    assert len({r["model"].to_json() for r in serial}) == 3
    # The refused unit says why and leaves nothing behind.
    bad = parallel[-1]
    assert bad["model"] is None and "missing required column 'temp_fog_degc'" in bad["error"]
    assert not (tmp_path / "models" / "unit4.json").exists()




def test_models_that_would_overwrite_each_other_are_refused_before_training(units, tmp_path):
    paths, _ = units
    other = tmp_path / "elsewhere" / paths[0].name
    other.parent.mkdir()
    other.symlink_to(paths[0], target_is_directory=True)
    trained = []
    with pytest.raises(ValueError, match="option out: two campaigns have the same folder name"):
        train_fleet([paths[0], other], out=tmp_path / "models", method="svr",
                    progress=lambda done, total, r: trained.append(done))
    assert trained == [] and not (tmp_path / "models").exists()


def test_a_unit_whose_evaluation_fails_gives_no_model(units, tmp_path):
    # Found by a new user (issue 35): the unit was reported failed and its model returned and
    # written all the same.
    import shutil
    paths, _ = units
    unit = tmp_path / "unit5"
    shutil.copytree(paths[0], unit)
    manifest = json.loads((unit / "campaign.json").read_text())
    test_file = next(r["file"] for r in manifest["recordings"] if r["role"] == "test")
    (unit / test_file).write_text("time_s,gyro_dph\n0,1\n")  # training does not read it
    [r] = train_fleet([unit], out=tmp_path / "models", method="poly")
    assert "missing required column" in r["error"]
    assert r["model"] is None and r["summary"] is None and r["evaluation"] is None
    assert not (tmp_path / "models" / "unit5.json").exists()


def test_options_are_checked_once_before_any_unit_runs(units, tmp_path):
    # Found by a new user (issue 35): a wrong method was reported once per unit, after each
    # had started.
    paths, _ = units
    for options, message in [(dict(method="svm"), "option method: 'svm' is not a method"),
                             (dict(population=1), "option population: 1 must be ≥ 2"),
                             (dict(c_min=10.0, c_max=1.0), "option c_max"),
                             (dict(method="poly", max_degree=9), "option max_degree: 9 must be between 1 and 6")]:
        ran = []
        with pytest.raises(ValueError, match=message):
            train_fleet(paths, out=tmp_path / "models",
                        progress=lambda done, total, r: ran.append(done), **options)
        assert ran == [] and not (tmp_path / "models").exists()


def test_each_units_warnings_are_raised_in_the_caller_naming_the_unit(units):
    paths, _ = units
    # A box far too small for C: the held-out estimate warns, on a worker as at home.
    options = dict(population=5, iterations=2, c_min=0.01, c_max=0.012)
    with pytest.warns(UserWarning) as serial:
        results = train_fleet(paths[:2], **options)
    assert {str(w.message).split(":")[0] for w in serial} == {"unit1", "unit2"}
    assert all(r["warnings"] for r in results)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        with pytest.warns(UserWarning) as parallel:
            train_fleet(paths[:2], client=client, **options)
    assert sorted(str(w.message) for w in parallel) == sorted(str(w.message) for w in serial)


def test_a_misspelt_keyword_and_a_wrong_campaign_are_named(units):
    paths, _ = units
    with pytest.raises(TypeError, match=r"train_fleet\(\) got an unexpected keyword argument "
                                        r"'popluation'; its keywords are client, out"):
        train_fleet(paths, popluation=5)
    with pytest.raises(TypeError, match=r"train_fleet\(\): campaigns\[1\] must be a folder .* "
                                        r"not int"):
        train_fleet([paths[0], 3])


def test_campaigns_in_memory_train_as_their_folders(units, tmp_path):
    paths, _ = units
    held = fogdrift.simulate("calibration", seed=1, temps_degc=[-20, 10, 40], repetitions=2)
    options = dict(population=5, iterations=2, evaluate=False)
    from_memory = train_fleet([held], out=tmp_path, **options)
    from_folder = train_fleet([paths[0]], **options)
    assert from_memory[0]["unit"] == "unit 1" and from_folder[0]["unit"] == "unit1"
    assert from_memory[0]["model"].to_json() == from_folder[0]["model"].to_json()
    assert (tmp_path / "unit 1.json").read_text() == from_folder[0]["model"].to_json()
