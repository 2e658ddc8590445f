"""Runs docs/tutorial.md as written: every command of its ```sh blocks, in order, in a scratch copy
of the repository's studies/ and plots/ with build/bin/hpcontact linked to the built program.
Each command must exit with 0, and the numbers the tutorial prints as a command's output
('# <problem>: energy = E', 'alpha ≈ A') must be what the command prints: energies to 1e-8
relative, α to the digits shown.

usage: run_tutorial.py CLI SOURCE_DIR SCRATCH_DIR
"""

import os
import re
import shutil
import subprocess
import sys


def commands_of(markdown):
    """(command, expected-output comment lines) in the order of the ```sh blocks."""
    commands = []
    for block in re.findall(r"```sh\n(.*?)```", markdown, re.S):
        for line in block.splitlines():
            if line.startswith("#"):
                if commands:
                    commands[-1][1].append(line)
            elif line.strip():
                commands.append((line, []))
    return commands


def check_numbers(command, expected, output):
    """The energies and α the tutorial shows for `command` are in its output."""
    problems = []
    for line in expected:
        match = re.match(r"#\s*(\w+): energy = (\S+?),", line)
        if not match:
            continue
        problem, energy = match.group(1), float(match.group(2))
        printed = re.search(rf"^{problem}: energy = (\S+?),", output, re.M)
        if not printed:
            problems.append(f"no '{problem}: energy' line")
        elif abs(float(printed.group(1)) - energy) > 1e-8 * max(abs(energy), 1e-12):
            problems.append(f"{problem}: energy {printed.group(1)}, the tutorial says {energy}")
    shown = re.search(r"#\s*alpha ≈ ([0-9.]+)", command)
    if shown:
        digits = len(shown.group(1).split(".")[1])
        printed = re.search(r"^alpha = (\S+)", output, re.M)
        if not printed or abs(float(printed.group(1)) - float(shown.group(1))) > 0.51 * 10 ** -digits:
            problems.append(f"alpha {printed.group(1) if printed else '(none)'}, the tutorial says {shown.group(1)}")
    return problems


def main():
    cli, source, scratch = sys.argv[1:4]
    if os.path.exists(scratch):
        shutil.rmtree(scratch)
    os.makedirs(os.path.join(scratch, "build", "bin"))
    for folder in ("studies", "plots"):
        shutil.copytree(os.path.join(source, folder), os.path.join(scratch, folder))
    os.symlink(os.path.abspath(cli), os.path.join(scratch, "build", "bin", "hpcontact"))
    with open(os.path.join(source, "docs", "tutorial.md"), encoding="utf-8") as handle:
        commands = commands_of(handle.read())
    if not commands:
        sys.exit("run_tutorial: no commands found in docs/tutorial.md")
    failures = []
    for command, expected in commands:
        print(f"$ {command}", flush=True)
        run = subprocess.run(command, shell=True, cwd=scratch, capture_output=True, text=True)
        print(run.stdout + run.stderr, flush=True)
        if run.returncode != 0:
            failures.append(f"'{command}' exited with {run.returncode}")
            continue
        failures += [f"'{command}': {problem}" for problem in check_numbers(command, expected, run.stdout)]
    if failures:
        sys.exit("docs/tutorial.md does not run as written:\n  " + "\n  ".join(failures))
    print(f"run_tutorial: {len(commands)} commands ran as written")


if __name__ == "__main__":
    main()
