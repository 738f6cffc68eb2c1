"""The workflow's configuration (workflow/config.yaml and `--config key=value`), checked as a scene is: every
key known, every value of the type the workflow uses it as. A bad one stops every command with one line that
names the key, the value and where it came from, before anything runs."""

from __future__ import annotations

import math
from pathlib import Path

import yaml

FLAGS = {"quick": False, "jobserver": True}  # 0 or 1, and the default
BUDGET = ("seconds", "memory_mb")
KNOWN = (*FLAGS, "budget", "archive")


class ConfigError(ValueError):
    """A configuration value the workflow cannot use; str(error) is one line."""


def check_config(config: dict, config_file: Path | str) -> dict:
    """{quick, jobserver: bool}, once every key of `config` (Snakemake's, the file's merged with the command
    line's) is one the workflow knows and holds what it expects; else ConfigError."""
    path = Path(config_file)
    try:
        in_file = yaml.safe_load(path.read_text(encoding="utf-8")) if path.is_file() else {}
    except yaml.YAMLError as error:
        raise ConfigError(f"{path}: not YAML ({str(error).splitlines()[0]})") from None
    in_file = in_file if isinstance(in_file, dict) else {}

    def refuse(key, value, expected, filed):
        origin = path.as_posix() if filed else "the command line (--config)"
        raise ConfigError(f"{origin}: config '{key}': expected {expected}, got {value!r}")

    for key, value in config.items():
        filed = key in in_file and in_file[key] == value
        if key not in KNOWN:
            refuse(key, value, "one of the keys " + ", ".join(KNOWN), filed)
        if key in FLAGS and not (isinstance(value, bool) or (isinstance(value, int) and value in (0, 1))):
            refuse(key, value, "0 or 1", filed)
        if key == "archive" and not (isinstance(value, str) and value.strip()):
            refuse(key, value, "the path of a dist archive", filed)
        if key == "budget":
            if not isinstance(value, dict):
                refuse(key, value, "a mapping such as {seconds: 900, memory_mb: 6000}", filed)
            filed_budget = in_file.get("budget") if isinstance(in_file.get("budget"), dict) else {}
            for part, amount in value.items():
                filed = part in filed_budget and filed_budget[part] == amount
                if part not in BUDGET:
                    refuse(f"budget.{part}", amount, "one of " + ", ".join(BUDGET), filed)
                number = isinstance(amount, (int, float)) and not isinstance(amount, bool)
                if not (number and 0 < amount < math.inf):
                    refuse(f"budget.{part}", amount, "a positive number", filed)
    return {key: bool(config.get(key, default)) for key, default in FLAGS.items()}
