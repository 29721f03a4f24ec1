"""Reinforcement-learning baselines of the paper's Table 1 (the ``baselines`` extra:
``pip install "./python[baselines]"``; PyTorch, Stable-Baselines3, sb3-contrib, matplotlib).

- ``python -m behavior.baselines.ppo ACTIVITY --row ROW``: PPO on the primitive action space
  (``--masked``: sb3-contrib's MaskablePPO, choosing among feasible primitives only).
- ``python -m behavior.baselines.sac ACTIVITY --row ROW``: SAC on the continuous action space.
- ``python -m behavior.baselines.table1 --row ROW``: a row on Table 1's 12 activities, with
  several seeds: its table beside the paper's and the training curves.

``rows`` holds the rows' configurations, ``extractor`` the original's network (a CNN per image,
a layer per vector), ``training`` what every run shares (the environment, the curve, the
evaluation, the run's folder).
"""
