"""The machine right-hand side written again in plain numpy: the peer a user would write for scipy.

Same equations as :func:`auxbearing.core.machine.rhs` (rigid rotor with static and couple unbalance and
gyroscopics, up to two touchdown planes with the journal/race line contact, an optional collar on the
race face, the ball set, its damping and rolling resistance, Palmgren's load-free torque, a mount with
dead band and hard stop, and the energy ledger), with every parameter read from the kernel's NamedTuples
(``pack(machine).machine``). The rotor and contact algebra is scalar Python (``math``); the ball set is
vectorised over balls and pairs in numpy, with the K_b(alpha) table of ``BallSet.tables`` read by the same
cubic Hermite interpolation as :func:`auxbearing.core.ballset.table`. Nothing here is compiled.

``make_rhs(core)`` returns ``f(t, y) -> dy/dt`` for :func:`scipy.integrate.solve_ivp`;
``normal_forces(states, core)`` gives the journal/race contact force of each plane on many states.
"""

from __future__ import annotations

import math

import numpy as np

from auxbearing.core import machine as cm
from auxbearing.core.bearing_friction import (
    PALMGREN_LOW_SPEED_PRODUCT,
    PALMGREN_LOW_SPEED_SCALE,
    PALMGREN_VISCOUS_SCALE,
)

#: Catalogue units of Palmgren's formula (Harris & Kotzalas 2007, Essential Concepts, Ch. 10).
M2S_TO_MM2S, RADS_TO_RPM, M_TO_MM, NMM_TO_NM = 1e6, 30.0 / math.pi, 1e3, 1e-3


def hermite(tables: np.ndarray, step: float, row: int, x: np.ndarray) -> np.ndarray:
    """Cubic Hermite value of table ``row`` at x (constant beyond the last node and below 0)."""
    values, slopes = tables[row, 0], tables[row, 1]
    n = values.size
    x = np.maximum(x, 0.0)
    i = np.minimum((x / step).astype(np.int64), n - 2)
    t = (x - i * step) / step
    t2, t3 = t * t, t * t * t
    out = ((2.0 * t3 - 3.0 * t2 + 1.0) * values[i] + (t3 - 2.0 * t2 + t) * slopes[i] * step
           + (3.0 * t2 - 2.0 * t3) * values[i + 1] + (t3 - t2) * slopes[i + 1] * step)
    return np.where(x >= (n - 1) * step, values[n - 1], out)


def ballset_force(bs, pd: float, axial: float, dx: float, dy: float) -> tuple[float, float, float]:
    """Resultant (Fz, Fx, Fy) of the ball set ON the inner race [N], untilted race, all balls and pairs at once."""
    signs = bs.signs[None, :]
    cphi, sphi = bs.cos_azimuth[:, None], bs.sin_azimuth[:, None]
    big_a = bs.curvature_distance
    a0 = signs * big_a * bs.sin_free_angle
    r0 = big_a * bs.cos_free_angle - 0.5 * pd
    radial = dx * cphi + dy * sphi
    excess = pd * (0.25 * pd - big_a * bs.cos_free_angle) + axial * (2.0 * a0 + axial) + radial * (2.0 * r0 + radial)
    a = a0 + axial
    r = r0 + radial
    s_len = np.sqrt(a * a + r * r)
    delta = excess / (s_len + big_a)
    k_b = hermite(bs.constant_table[None], bs.constant_step, 0, r / s_len)  # K_b on cos(alpha), as the kernel
    q = np.where((excess > 0.0) & (delta > 0.0), k_b * np.maximum(delta, 0.0) ** 1.5, 0.0)
    fz = -q * a / s_len
    fr = -q * r / s_len
    return float(fz.sum()), float((fr * cphi).sum()), float((fr * sphi).sum())


def palmgren(nu: float, speed: float, dm: float, f0: float) -> float:
    """Palmgren's load-free torque M_0 [N m] (Harris & Kotzalas 2007, Essential Concepts, Ch. 10)."""
    product = nu * M2S_TO_MM2S * abs(speed) * RADS_TO_RPM
    scale = PALMGREN_VISCOUS_SCALE * product ** (2.0 / 3.0) if product >= PALMGREN_LOW_SPEED_PRODUCT \
        else PALMGREN_LOW_SPEED_SCALE
    return scale * f0 * (dm * M_TO_MM) ** 3 * NMM_TO_NM


def friction(mu_fn: float, vx: float, vy: float, vz: float, v_eps: float) -> tuple[float, float, float]:
    speed = math.sqrt(vx * vx + vy * vy + vz * vz)
    if speed == 0.0 or mu_fn == 0.0:
        return 0.0, 0.0, 0.0
    scale = -mu_fn * math.tanh(speed / v_eps) / speed
    return scale * vx, scale * vy, scale * vz


def make_rhs(core):
    """dy/dt of the machine ``core`` (an :class:`auxbearing.core.machine.Machine`) as ``f(t, y)``."""
    rot = core.rotor
    p = core.planes
    planes = [k for k in range(len(p.active)) if p.active[k] > 0.0]
    at = cm.layout_of(core)

    def rhs(t, y):
        out = np.zeros(at.size)
        om = y[cm.OMEGA]
        be, bc = y[cm.PHI] + rot.unbalance_phase, y[cm.PHI] + rot.couple_phase
        e, chi = rot.unbalance, rot.couple_unbalance
        eux, euy = -e * math.sin(be), e * math.cos(be)
        cwx, cwy = -chi * math.sin(bc), chi * math.cos(bc)
        cwpx, cwpy = -chi * math.cos(bc), -chi * math.sin(bc)
        tpx, tpy = y[cm.TX] + cwx, y[cm.TY] + cwy
        wpx, wpy = y[cm.WX] + cwpx * om, y[cm.WY] + cwpy * om
        q = [0.0] * 6

        def velocity(a, rx_, ry_):
            return (y[cm.VX] + a * y[cm.WY] - om * ry_, y[cm.VY] - a * y[cm.WX] + om * rx_,
                    y[cm.VZ] + wpx * ry_ - wpy * rx_ + om * (tpx * rx_ + tpy * ry_))

        def push(a, rx_, ry_, fx, fy, fz):
            q[0] += fx
            q[1] += fy
            q[2] += fz
            q[3] += -a * fy + ry_ * fz
            q[4] += a * fx - rx_ * fz
            q[5] += fx * (-eux - a * cwpy - ry_) + fy * (-euy + a * cwpx + rx_) + fz * (tpx * rx_ + tpy * ry_)

        for k in planes:
            b = cm.N_ROTOR + k * cm.N_PLANE
            heat = at.heat_at + 3 * k
            a, r, s, veps = p.position[k], p.journal_radius[k], p.clearance[k], p.slip_velocity[k]
            jx, jy = y[cm.X] + a * y[cm.TY], y[cm.Y] - a * y[cm.TX]
            rx, ry, rz = y[b + cm.RX], y[b + cm.RY], y[b + cm.RZ]
            rvx, rvy, rvz, rw = y[b + cm.RVX], y[b + cm.RVY], y[b + cm.RVZ], y[b + cm.ROMEGA]
            fx_r = fy_r = fz_r = t_r = 0.0
            dx, dy = jx - rx, jy - ry
            dist = math.sqrt(dx * dx + dy * dy)
            if dist - s > 0.0:  # journal on the race bore
                nx, ny = dx / dist, dy / dist
                vpx, vpy, vpz = velocity(a, r * nx, r * ny)
                arm = r + s
                dvx, dvy, dvz = vpx - (rvx - rw * arm * ny), vpy - (rvy + rw * arm * nx), vpz - rvz
                vn = dvx * nx + dvy * ny
                elastic = p.line_stiffness[k] * (dist - s) ** (10.0 / 9.0)
                fn = max(0.0, elastic + p.line_damping[k] * vn)
                sx, sy = dvx - vn * nx, dvy - vn * ny
                ffx, ffy, ffz = friction(p.sliding_friction[k] * fn, sx, sy, dvz, veps)
                cfx, cfy = -fn * nx + ffx, -fn * ny + ffy
                push(a, r * nx, r * ny, cfx, cfy, ffz)
                fx_r, fy_r, fz_r = -cfx, -cfy, -ffz
                t_r = -arm * (nx * cfy - ny * cfx)
                out[heat] += (fn - elastic) * vn - (ffx * sx + ffy * sy + ffz * dvz)
            zeta = y[cm.Z] - rz
            side, pen = 0.0, 0.0
            if p.face_plus[k] > 0.0 and zeta - p.axial_clearance[k] > 0.0:
                side, pen = 1.0, zeta - p.axial_clearance[k]
            elif p.face_minus[k] > 0.0 and -zeta - p.axial_clearance[k] > 0.0:
                side, pen = -1.0, -zeta - p.axial_clearance[k]
            if side != 0.0:  # collar on the race face
                cx, cy = rx - jx, ry - jy
                rate = side * (velocity(a, cx, cy)[2] - rvz)
                elastic = p.face_stiffness[k] * pen
                fa = max(0.0, elastic + p.face_damping[k] * rate)
                push(a, cx, cy, 0.0, 0.0, -side * fa)
                fz_r += side * fa
                out[heat] += (fa - elastic) * rate
                share, rf = p.face_friction[k] * fa / cm.FACE_POINTS, p.face_radius[k]
                for i in range(cm.FACE_POINTS):
                    beta = 2.0 * math.pi * i / cm.FACE_POINTS
                    ox, oy = rf * math.cos(beta), rf * math.sin(beta)
                    vax, vay, _ = velocity(a, cx + ox, cy + oy)
                    slip_x, slip_y = vax - (rvx - rw * oy), vay - (rvy + rw * ox)
                    gx, gy, _ = friction(share, slip_x, slip_y, 0.0, veps)
                    push(a, cx + ox, cy + oy, gx, gy, 0.0)
                    fx_r, fy_r = fx_r - gx, fy_r - gy
                    t_r -= ox * gy - oy * gx
                    out[heat] -= gx * slip_x + gy * slip_y
            ox_, oy_, ovx, ovy = y[b + cm.OX], y[b + cm.OY], y[b + cm.OVX], y[b + cm.OVY]
            fz_b, fex, fey = ballset_force(core.ballsets[k], core.ballset_clearance[k], rz, rx - ox_, ry - oy_)
            fez = fz_b if p.race_axial_free[k] > 0.0 else 0.0
            cb = p.ball_damping[k]
            relx, rely, relz = rvx - ovx, rvy - ovy, rvz
            fx_r += fex - cb * relx
            fy_r += fey - cb * rely
            fz_r += fez - cb * relz
            out[heat + 1] += cb * (relx * relx + rely * rely + relz * relz)
            out[at.ballset_work] -= fex * relx + fey * rely + fez * relz
            ring_fx, ring_fy = -fex + cb * relx, -fey + cb * rely
            fe = math.sqrt(fex * fex + fey * fey)
            mu2, ri = p.rolling_friction[k], p.raceway_radius[k]
            spin_sign = math.tanh(rw * ri / veps)
            if fe > 0.0 and mu2 > 0.0:  # rolling resistance at the loaded zone
                ux, uy = -fex / fe, -fey / fe
                roll = -mu2 * fe * spin_sign
                fx_r, fy_r, t_r = fx_r - roll * uy, fy_r + roll * ux, t_r + ri * roll
                ring_fx, ring_fy = ring_fx + roll * uy, ring_fy - roll * ux
                out[heat + 1] -= roll * (-uy * relx + ux * rely + ri * rw)
            torque = mu2 * abs(fez) * ri
            if p.viscous_factor[k] > 0.0:
                torque += palmgren(p.lubricant_viscosity[k], rw, p.pitch_diameter[k], p.viscous_factor[k])
            if torque > 0.0:
                t_r -= torque * spin_sign
                out[heat + 1] += torque * spin_sign * rw
            mr = p.race_mass[k]
            out[b + cm.RX], out[b + cm.RY], out[b + cm.RPSI] = rvx, rvy, rw
            out[b + cm.RVX] = fx_r / mr + rot.gravity_x
            out[b + cm.RVY] = fy_r / mr + rot.gravity_y
            out[b + cm.ROMEGA] = t_r / p.race_inertia[k]
            if p.race_axial_free[k] > 0.0:
                out[b + cm.RZ], out[b + cm.RVZ] = rvz, fz_r / mr + rot.gravity_z
            if p.ring_free[k] > 0.0:  # outer ring in its mount
                ux_, uy_ = ox_ - p.centre_x[k], oy_ - p.centre_y[k]
                travel = math.sqrt(ux_ * ux_ + uy_ * uy_)
                spring = p.mount_stiffness[k] * max(0.0, travel - p.mount_deadband[k])
                stop = 0.0
                if travel > p.stop_gap[k]:
                    stop_rate = (ux_ * ovx + uy_ * ovy) / travel
                    stop_elastic = p.stop_stiffness[k] * (travel - p.stop_gap[k])
                    stop = max(0.0, stop_elastic + p.stop_damping[k] * stop_rate)
                    out[heat + 2] += (stop - stop_elastic) * stop_rate
                if travel > 0.0:
                    ring_fx -= (spring + stop) * ux_ / travel
                    ring_fy -= (spring + stop) * uy_ / travel
                cm_ = p.mount_damping[k]
                ring_fx, ring_fy = ring_fx - cm_ * ovx, ring_fy - cm_ * ovy
                out[heat + 2] += cm_ * (ovx * ovx + ovy * ovy)
                out[b + cm.OX], out[b + cm.OY] = ovx, ovy
                out[b + cm.OVX] = ring_fx / p.ring_mass[k] + rot.gravity_x
                out[b + cm.OVY] = ring_fy / p.ring_mass[k] + rot.gravity_y
        q[0] += rot.force_x
        q[1] += rot.force_y
        q[2] += rot.force_z
        drag = -(rot.drag_constant * math.tanh(om / rot.drag_speed_scale) + rot.drag_viscous * om
                 + rot.drag_windage * om * abs(om))
        q[5] += drag + rot.process_torque
        out[at.work_in] = (rot.force_x * (y[cm.VX] + eux * om) + rot.force_y * (y[cm.VY] + euy * om)
                        + rot.force_z * y[cm.VZ] + rot.process_torque * om)
        out[at.drag_loss] = -drag * om
        spin_acc = q[5] / rot.polar_inertia
        out[cm.X], out[cm.Y], out[cm.PHI] = y[cm.VX], y[cm.VY], om
        out[cm.VX] = q[0] / rot.mass + rot.gravity_x + e * math.cos(be) * om * om - eux * spin_acc
        out[cm.VY] = q[1] / rot.mass + rot.gravity_y + e * math.sin(be) * om * om - euy * spin_acc
        out[cm.OMEGA] = spin_acc
        if rot.axial_free:
            out[cm.Z], out[cm.VZ] = y[cm.VZ], q[2] / rot.mass + rot.gravity_z
        if rot.tilt_free:  # gyroscopic rigid rotor, principal axis = geometric axis + chi w
            gyro = rot.polar_inertia * om
            out[cm.TX], out[cm.TY] = y[cm.WX], y[cm.WY]
            out[cm.WX] = (q[3] - gyro * wpy) / rot.transverse_inertia + cwx * om * om - cwpx * spin_acc
            out[cm.WY] = (q[4] + gyro * wpx) / rot.transverse_inertia + cwy * om * om - cwpy * spin_acc
        return out

    return rhs


def normal_forces(states: np.ndarray, core) -> np.ndarray:
    """Journal/race contact force F_n of each active plane [N] on states of shape (n, state size); (n, planes)."""
    p = core.planes
    y = states.T
    cols = []
    for k in range(len(p.active)):
        if p.active[k] <= 0.0:
            continue
        b = cm.N_ROTOR + k * cm.N_PLANE
        a = p.position[k]
        dx = y[cm.X] + a * y[cm.TY] - y[b + cm.RX]
        dy = y[cm.Y] - a * y[cm.TX] - y[b + cm.RY]
        dist = np.hypot(dx, dy)
        delta = dist - p.clearance[k]
        dist = np.where(dist > 0.0, dist, 1.0)  # a centred journal: no contact, any direction
        # the spin moves the contact point along the tangent only: the normal rate is the axis point's
        vn = ((y[cm.VX] + a * y[cm.WY] - y[b + cm.RVX]) * dx + (y[cm.VY] - a * y[cm.WX] - y[b + cm.RVY]) * dy) / dist
        fn = p.line_stiffness[k] * np.maximum(delta, 0.0) ** (10.0 / 9.0) + p.line_damping[k] * vn
        cols.append(np.where(delta > 0.0, np.maximum(fn, 0.0), 0.0))
    return np.stack(cols, axis=1)
