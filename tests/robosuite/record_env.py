"""Run one robosuite environment in this process and record it: ``python -m tests.robosuite.record_env
stock|specs ENV ROBOT[,ROBOT] STEPS OUT`` writes ``OUT.mjb`` (the compiled world) and ``OUT.npz`` (every
observation and reward over STEPS seeded random actions).

Each side runs in its own process: two stock environments with mobile robots stepped in one process
already differ at the first step (robosuite's state is not per environment), so a comparison in one
process would not show what it claims.
"""

from __future__ import annotations

import sys

import mujoco
import numpy as np


def record(side: str, env_name: str, robots: list[str], steps: int, out: str) -> None:
    """Make the environment (robosuite's robots, or our specs of them), step it and write the record."""
    import robosuite

    from assembler.robosuite import compat

    compat.apply_all()  # what this MuJoCo needs patched in robosuite (nothing on 3.9): both sides alike
    if side == "specs":
        import assembler.robosuite

        assembler.robosuite.replace_robosuite()
    options = {"has_renderer": False, "has_offscreen_renderer": False, "use_camera_obs": False, "seed": 0}
    if env_name.startswith("TwoArm") and len(robots) == 1:
        options["env_configuration"] = "single-robot"
    env = robosuite.make(
        env_name, robots=robots if len(robots) > 1 else robots[0], ignore_done=True, **options
    )
    observations = env.reset()
    mujoco.mj_saveModel(env.sim.model._model, f"{out}.mjb", None)
    rng = np.random.default_rng(1)
    low, high = (np.clip(bound, -1, 1) for bound in env.action_spec)
    recorded = {f"0/{key}": np.asarray(value, dtype=float) for key, value in observations.items()}
    for step in range(1, steps + 1):
        observations, reward, _, _ = env.step(rng.uniform(low, high))
        recorded.update(
            {f"{step}/{key}": np.asarray(value, dtype=float) for key, value in observations.items()}
        )
        recorded[f"{step}/reward"] = np.array(reward, dtype=float)
    np.savez(f"{out}.npz", **recorded)


if __name__ == "__main__":
    side, env_name, robots, steps, out = sys.argv[1:6]
    record(side, env_name, robots.split(","), int(steps), out)
