"""The original RL baseline's network in front of the policy (BEHAVIOR's `BehaviorExtractor`): each image through
its own CNN (32 8×8 stride 4, 64 4×4 stride 2, 64 3×3 stride 1, then 128 units), each vector
(``proprioception``, ``task_obs``, ``lidar``) through 128 units, the features concatenated.

Images come as the environment gives them: ``rgb`` ``(s, s, 3)`` uint8 (Stable-Baselines3
turns it channels-first and scales it to [0, 1] before it gets here), ``depth`` ``(s, s)`` in
metres (clipped to 10 m and divided by 10, as the original does), other 2-D images as one channel.
"""

import gymnasium
import numpy as np
import torch
from stable_baselines3.common.torch_layers import BaseFeaturesExtractor
from torch import nn

# Units after each image's CNN and after each vector's layer (the original's).
FEATURES = 128
# Depth beyond this (m) reads as this, and depth is divided by it.
DEPTH_RANGE = 10.0


def _channels_first(shape) -> bool:
    """Whether a 3-D image is laid out (channels, height, width)."""
    return shape[0] in (1, 3, 4) and shape[-1] not in (1, 3, 4)


class _Image(nn.Module):
    """One image's CNN."""

    def __init__(self, name: str, space: gymnasium.spaces.Box):
        super().__init__()
        shape = space.shape
        self.depth = name == "depth"
        if len(shape) == 2:
            self.layout, channels = "hw", 1
        elif _channels_first(shape):
            self.layout, channels = "chw", shape[0]
        else:
            self.layout, channels = "hwc", shape[-1]
        self.cnn = nn.Sequential(
            nn.Conv2d(channels, 32, kernel_size=8, stride=4),
            nn.ReLU(),
            nn.Conv2d(32, 64, kernel_size=4, stride=2),
            nn.ReLU(),
            nn.Conv2d(64, 64, kernel_size=3, stride=1),
            nn.ReLU(),
            nn.Flatten(),
        )
        with torch.no_grad():
            flat = self.cnn(self._layout(torch.zeros((1, *shape)))).shape[1]
        self.head = nn.Sequential(nn.Linear(flat, FEATURES), nn.ReLU())

    def _layout(self, x: torch.Tensor) -> torch.Tensor:
        if self.layout == "hw":
            x = x.unsqueeze(1)
        elif self.layout == "hwc":
            x = x.permute(0, 3, 1, 2)
        if self.depth:
            x = x.clamp(0.0, DEPTH_RANGE) / DEPTH_RANGE
        return x

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return self.head(self.cnn(self._layout(x.float())))


class BehaviorExtractor(BaseFeaturesExtractor):
    """The features of a ``Dict`` observation: a CNN per image, a layer per vector."""

    def __init__(self, observation_space: gymnasium.spaces.Dict):
        parts = {}
        for name, space in observation_space.spaces.items():
            if len(space.shape) >= 2:
                parts[name] = _Image(name, space)
            else:
                parts[name] = nn.Sequential(
                    nn.Linear(int(np.prod(space.shape)), FEATURES), nn.ReLU()
                )
        super().__init__(observation_space, features_dim=FEATURES * len(parts))
        self.parts = nn.ModuleDict(parts)

    def forward(self, observations: dict) -> torch.Tensor:
        return torch.cat(
            [part(observations[name].float()) for name, part in self.parts.items()], dim=1
        )
