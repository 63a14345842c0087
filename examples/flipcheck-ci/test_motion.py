"""An engine's CI test (pytest): the motion file its run wrote, judged by flipcheck."""
import os
import numpy as np
from bookspin import flipcheck

def test_the_engines_motion_passes():
    path = os.environ.get("MOTION", "motion.csv")  # t,qw,qx,qy,qz,wx_world,wy_world,wz_world
    m = np.genfromtxt(path, delimiter=",", names=True)
    q = np.column_stack([m["qw"], m["qx"], m["qy"], m["qz"]])
    w = np.column_stack([m["wx_world"], m["wy_world"], m["wz_world"]])
    flipcheck.assert_passes("book-intermediate-0.05", m["t"], q, w, motion=os.path.basename(path))
