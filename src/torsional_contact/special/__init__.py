"""Special functions of the problem: zeros of J2 (eq. 19-20) and the closed forms of eqs. 35, 51-53."""
