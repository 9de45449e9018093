"""Camera matrices shared by the tests (y up, the camera looking along −z in eye space)."""
import numpy as np


def look(eye, direction):
    """The world → eye matrix of a camera at ``eye`` looking along ``direction`` (y up)."""
    d = np.asarray(direction, float) / np.linalg.norm(direction)
    right = np.cross(d, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, d)
    eye_to_world = np.eye(4)
    eye_to_world[:3, 0], eye_to_world[:3, 1], eye_to_world[:3, 2] = right, up, -d
    eye_to_world[:3, 3] = eye
    return np.linalg.inv(eye_to_world)


def look_at(eye, target):
    """The world → eye matrix of a camera at ``eye`` looking at ``target`` (y up)."""
    return look(eye, np.asarray(target, float) - np.asarray(eye, float))
