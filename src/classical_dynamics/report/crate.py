"""The RO-Crate of an archive (issue 36, item 2): ro-crate-metadata.json, made with the rocrate library.

Profiles: Workflow Run Crate 0.5 (the Snakefile the mainEntity; one CreateAction for the run: instrument the
workflow, object the configuration and each scene, result each results file with its SHA-256 and the report)
and, per job, Provenance Run Crate 0.5 (one CreateAction for each scene folder with a provenance record,
with its ControlAction and the OrganizeAction of Snakemake). The software is named with its versions from
requirements/pipeline.lock; the license and the citation are files of the crate.

Deterministic: no time of "now" (the run's times are its scenes' provenance times; the crate's date is the
last of them, or CITATION.cff's date-released without any), entities in a fixed order.
"""

from __future__ import annotations

import datetime
import mimetypes
import re
from pathlib import Path, PurePosixPath

CRATE_VERSION = "1.1"  # the RO-Crate version the Workflow Run Crate profiles 0.5 build on
PROFILES = {
    "https://w3id.org/ro/wfrun/process/0.5": "Process Run Crate",
    "https://w3id.org/ro/wfrun/workflow/0.5": "Workflow Run Crate",
    "https://w3id.org/ro/wfrun/provenance/0.5": "Provenance Run Crate",
    "https://w3id.org/workflowhub/workflow-ro-crate/1.0": "Workflow RO-Crate",
}
# Terms of the Workflow Run Crate context used here, inline: a reader (and the validator) needs no download.
TERMS = {"sha256": "https://w3id.org/ro/terms/workflow-run#sha256"}
LOCK = "requirements/pipeline.lock"
LICENSE_URL = {"MIT": "https://spdx.org/licenses/MIT"}
# The checkout's files the crate describes, packed beside the results (and the Snakefile, found as Snakemake
# finds it)
CHECKOUT_FILES = ("LICENSE", "CITATION.cff", LOCK)
REPORT = ("report.html", "report.pdf")
FORMATS = {
    ".yaml": "application/yaml",
    ".csv": "text/csv",
    ".json": "application/json",
    ".cff": "application/yaml",
}


def snakefile_choices() -> list[PurePosixPath]:
    """Where Snakemake looks for the Snakefile from the working directory, in its order."""
    try:
        from snakemake.common import SNAKEFILE_CHOICES
    except ImportError:  # the same list, as snakemake 9 has it
        SNAKEFILE_CHOICES = ["Snakefile", "snakefile", "workflow/Snakefile", "workflow/snakefile"]
    return [PurePosixPath(choice) for choice in SNAKEFILE_CHOICES]


def find_checkout(results_dir: Path, snakefile: Path | None = None) -> tuple[Path, PurePosixPath]:
    """(the checkout's root, the Snakefile relative to it): from the Snakefile Snakemake ran, else the first
    of the results folder's parent, this package's checkout and the working directory that has one."""
    if snakefile is not None:  # the checkout is the nearest folder above it with the project's pyproject.toml
        snakefile = Path(snakefile).resolve()
        root = next((p for p in snakefile.parents if (p / "pyproject.toml").is_file()), snakefile.parent)
        return root, PurePosixPath(snakefile.relative_to(root).as_posix())
    candidates = [Path(results_dir).resolve().parent, Path(__file__).resolve().parents[3], Path.cwd()]
    for root in candidates:
        for choice in snakefile_choices():
            if (root / choice).is_file() and (root / "pyproject.toml").is_file():
                return root, choice
    raise FileNotFoundError(f"no Snakefile found in {', '.join(map(str, candidates))}")


def checkout_members(root: Path, snakefile: PurePosixPath) -> list[PurePosixPath]:
    """The checkout's files that an archive carries for its crate: the Snakefile, its configuration, the
    license, the citation and the lock."""
    config = PurePosixPath("workflow/config.yaml")  # beside the rules, wherever the Snakefile is
    return [snakefile] + [config] * (root / config).is_file() + [PurePosixPath(p) for p in CHECKOUT_FILES]


def lock_pins(text: str) -> dict[str, str]:
    """{name: version} of a pip-compile lock."""
    return dict(re.findall(r"^([A-Za-z0-9][A-Za-z0-9._-]*)==([^\s\\;]+)", text, flags=re.MULTILINE))


def _citation(text: str) -> dict[str, str]:
    """The top-level scalar fields of CITATION.cff (title, version, date-released, license)."""
    import yaml

    data = yaml.safe_load(text) or {}
    return {
        key: str(value) for key, value in data.items() if isinstance(value, (str, int, float, datetime.date))
    } | {
        "authors": [
            a.get("name") or " ".join(filter(None, (a.get("given-names"), a.get("family-names"))))
            for a in data.get("authors") or []
            if isinstance(a, dict)
        ]
    }


def _slug(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9._-]+", "-", text)


def build(
    root: Path,
    snakefile: PurePosixPath,
    sums: dict[str, str],
    provenance: dict[str, dict],
    project: dict,
    with_report: bool,
) -> bytes:
    """ro-crate-metadata.json for an archive whose members (but SHA256SUMS and the crate) are `sums`
    ({path inside the archive: sha256}); `provenance`: {scene folder: its provenance.json}."""
    from rocrate.model.contextentity import ContextEntity
    from rocrate.rocrate import ROCrate

    root = Path(root)
    citation = _citation((root / "CITATION.cff").read_text())
    pins = lock_pins((root / LOCK).read_text())
    started = sorted(str(p["started"]) for p in provenance.values() if p.get("started"))
    finished = sorted(str(p["finished"]) for p in provenance.values() if p.get("finished"))
    published = finished[-1] if finished else citation.get("date-released", "1970-01-01")

    crate = ROCrate(version=CRATE_VERSION)
    crate.metadata.extra_terms.update(TERMS)

    def context(identifier: str, properties: dict):
        return crate.add(ContextEntity(crate, identifier, properties=properties))

    def ref(entity):
        return {"@id": entity if isinstance(entity, str) else entity.id}

    title = citation.get("title", project["name"])
    licence_id = LICENSE_URL.get(citation.get("license", ""), citation.get("license", ""))
    licence = context(licence_id, {"@type": "CreativeWork", "name": f"{citation.get('license')} License"})
    creators = [
        context(f"#author-{_slug(name)}", {"@type": "Organization", "name": name})
        for name in citation["authors"]
    ]
    root_dataset = crate.root_dataset
    root_dataset["datePublished"] = published
    root_dataset["name"] = (
        f"{title}: {'results and report' if with_report else 'results'}, version {project['version']}"
    )
    root_dataset["description"] = (
        "The archive of a run of the workflow: every summary, table, figure and provenance record"
        + (", and the report" if with_report else "")
        + ", with a SHA256SUMS manifest, made by classical_dynamics.report.dist."
    )
    root_dataset["version"] = project["version"]
    root_dataset["license"] = licence
    if creators:
        root_dataset["creator"] = creators
    root_dataset["conformsTo"] = [
        context(uri, {"@type": "CreativeWork", "name": name, "version": uri.rsplit("/", 1)[1]})
        for uri, name in PROFILES.items()
    ]

    # The software: the pins of the lock; Snakemake is the workflow's language and engine
    software = {
        name: context(
            f"https://pypi.org/project/{name}/{version}/",
            {
                "@type": "SoftwareApplication",
                "name": name,
                "softwareVersion": version,
                "url": f"https://pypi.org/project/{name}/",
            },
        )
        for name, version in sorted(pins.items())
    }
    package = context(
        f"#{project['name']}",
        {
            "@type": "SoftwareApplication",
            "name": project["name"],
            "softwareVersion": project["version"],
            "description": project.get("description", ""),
        },
    )

    def add_file(path: str, **properties):
        properties.setdefault(
            "encodingFormat",
            FORMATS.get(PurePosixPath(path).suffix)
            or mimetypes.guess_type(path)[0]
            or "application/octet-stream",
        )
        if path in sums:
            properties["sha256"] = sums[path]
        return crate.add_file(dest_path=path, properties=properties)

    workflow = crate.add_workflow(
        dest_path=snakefile.as_posix(),
        main=True,
        lang="snakemake",
        lang_version=pins.get("snakemake"),
        properties={
            "@type": ["File", "SoftwareSourceCode", "ComputationalWorkflow", "HowTo"],
            "name": f"{title} (Snakemake workflow)",
            "version": project["version"],
            "sha256": sums[snakefile.as_posix()],
            "softwareRequirements": [ref(package)] + [ref(s) for s in software.values()],
        },
    )
    crate.root_dataset["conformsTo"] = [ref(uri) for uri in PROFILES]  # add_workflow set its own
    checkout = checkout_members(root, snakefile)
    config_path = next((p.as_posix() for p in checkout if p.name == "config.yaml"), None)
    config = add_file(config_path, name="The workflow's configuration") if config_path else None
    add_file(LOCK, name="The pinned software (pip-compile lock)", encodingFormat="text/plain")
    licence_file = add_file("LICENSE", name="License", encodingFormat="text/plain")
    licence["subjectOf"] = ref(licence_file)
    root_dataset["citation"] = ref(add_file("CITATION.cff", name="How to cite (Citation File Format)"))

    # Each scene folder as a Dataset of its files; the report's files; everything else of the results
    folders = {}
    for folder in sorted(provenance):
        folders[folder] = crate.add_dataset(dest_path=folder + "/", properties={"name": folder})
    files = {}
    for path in sorted(sums):
        if path in {p.as_posix() for p in checkout}:
            continue
        kind = "scene" if path.endswith("/scene.yaml") else "report" if path in REPORT else "result"
        files[path] = add_file(path, name=path)
        folder = str(PurePosixPath(path).parent)
        if folder in folders:
            folders[folder].append_to("hasPart", files[path])
        files[path]["description"] = {"scene": "a scene: the input of one job", "report": "the report"}.get(
            kind, "a result"
        )
    scenes = [f for p, f in files.items() if p.endswith("/scene.yaml")]
    results = [f for p, f in files.items() if not p.endswith("/scene.yaml")]

    # The run's parameter beyond the configuration file: quick (what every scene's provenance records)
    quick = sorted({bool(p["quick"]) for p in provenance.values() if "quick" in p})
    objects = ([config] if config else []) + scenes
    inputs = []
    if config:
        parameter = context(
            "#param-configfile",
            {
                "@type": "FormalParameter",
                "additionalType": "File",
                "name": "configfile",
                "workExample": ref(config),
            },
        )
        config["exampleOfWork"] = ref(parameter)
        inputs.append(parameter)
    if len(quick) == 1:
        value = context("#pv-quick", {"@type": "PropertyValue", "name": "quick", "value": quick[0]})
        parameter = context(
            "#param-quick",
            {
                "@type": "FormalParameter",
                "additionalType": "Boolean",
                "name": "quick",
                "description": "a reduced build (--config quick=1)",
                "workExample": ref(value),
            },
        )
        value["exampleOfWork"] = ref(parameter)
        inputs.append(parameter)
        objects.append(value)
    if inputs:
        workflow["input"] = [ref(p) for p in inputs]

    times = {"startTime": started[0], "endTime": finished[-1]} if started and finished else {}
    run = crate.add_action(
        workflow,
        identifier="#run",
        object=objects,
        result=results,
        properties={
            "@type": "CreateAction",
            "name": f"Run of {snakefile.as_posix()}",
            "description": "The run of the workflow whose results this archive holds",
            **times,
        },
    )

    # Per job (Provenance Run Crate): each scene folder's provenance record is one job of the workflow
    tools, controls = {}, []
    for folder in sorted(provenance):
        record = provenance[folder]
        rule = "self_excited_gallery" if "input_scenes" in record else "scene"
        if rule not in tools:
            tool = context(
                f"#rule-{rule}",
                {
                    "@type": "SoftwareApplication",
                    "name": f"rule {rule}",
                    "description": f"the Snakefile's rule {rule}, run with the package {project['name']}",
                    "softwareVersion": project["version"],
                },
            )
            step = context(
                f"#step-{rule}",
                {
                    "@type": "HowToStep",
                    "name": f"rule {rule}",
                    "workExample": ref(tool),
                    "position": str(len(tools)),
                },
            )
            tools[rule] = (tool, step)
            workflow.append_to("hasPart", tool)
            workflow.append_to("step", step)
        tool, step = tools[rule]
        if "input_scenes" in record:
            study = folder.split("/")[0]
            job_objects = [
                folders[f"{study}/{s}"] for s in record["input_scenes"] if f"{study}/{s}" in folders
            ]
        else:
            job_objects = [files[p] for p in (f"{folder}/scene.yaml",) if p in files]
        job_results = [
            files[f"{folder}/{n}"] for n in sorted(record.get("files") or {}) if f"{folder}/{n}" in files
        ]
        job_results += [files[p] for p in (f"{folder}/provenance.json",) if p in files]
        job_times = {
            k: str(record[v]) for k, v in (("startTime", "started"), ("endTime", "finished")) if record.get(v)
        }
        job = crate.add_action(
            tool,
            identifier=f"#job-{_slug(folder)}",
            object=job_objects or None,
            result=job_results or None,
            properties={
                "@type": "CreateAction",
                "name": f"rule {rule}: {folder}",
                "description": f"The job of rule {rule} that made {folder}/ (times from its provenance.json)",
                **job_times,
            },
        )
        controls.append(
            context(
                f"#control-{_slug(folder)}",
                {
                    "@type": "ControlAction",
                    "name": f"orchestrate {folder}",
                    "description": f"Snakemake's scheduling of the job that made {folder}/",
                    "instrument": ref(step),
                    "object": ref(job),
                },
            )
        )
    if controls:
        engine = software.get("snakemake") or context(
            "#snakemake", {"@type": "SoftwareApplication", "name": "snakemake"}
        )
        context(
            "#organize",
            {
                "@type": "OrganizeAction",
                "name": "Snakemake's run of the workflow",
                "description": "Snakemake running the workflow's jobs",
                "instrument": ref(engine),
                "object": [ref(c) for c in controls],
                "result": ref(run),
                **times,
            },
        )
    root_dataset["mentions"] = [
        ref(e) for e in crate.get_entities() if e.type in ("CreateAction", "ControlAction", "OrganizeAction")
    ]
    for entity in crate.get_entities():  # RO-Crate 1.1 prefers one value to a list of one
        for key, value in entity.properties().items():
            if isinstance(value, list) and len(value) == 1 and not key.startswith("@"):
                entity.properties()[key] = value[0]
    _, data = next(crate.metadata.stream())
    return data
