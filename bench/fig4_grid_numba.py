#!/usr/bin/python3
"""The Fig. 4 grid as an engineer's JIT-compiled script would compute it (docs/performance.md,
"The grid against a script"): the work of `shockmap study run studies/perf_grid.json`, written
with NumPy and Numba (Debian's python3-numba), for timing side by side.

    bench/fig4_grid_numba.py [OUT.db]

For 8 R_k from 1 to 1e6 and 5 R_ftrunc from 10 to 1000 (window 0.06 s, dt = 5e-6 s, 100
Hermite elements): one semi-analytical reference per R_k at R_fref = max(2000, 30 sqrt(R_k)) f1
(clamped-free modes below f_ref, the residual flexibility of the others in series with the spring,
the contact phase on the eigenvectors of the rank-one update; crossings bracketed every shortest
period / 16 by rotation and refined by regula falsi on the exact sum; output every shortest
period / 8), checked only against R_fref / 3 on the same grid (the largest tip difference over
the amplitude); per point the explicit modal run (central differences, penalty at the tip), Err
(eq. 8: Hann, 4096 points, padded 4x, one-sided) and SRf (first-shock impulses, contacts closer
than 0.1 T1 grouped). The scores go to an SQLite file when OUT.db is given. Numba's cache is
NUMBA_CACHE_DIR (or beside the script); the first run compiles, later runs load it.
"""

import math
import sqlite3
import sys
import time

import numpy as np
from numba import njit

LENGTH, EI, RHO_A = 1.0, 1.5e5, 127.0
MASS = RHO_A * LENGTH
K_BEND = 3.0 * EI / LENGTH**3
OMEGA_UNIT = math.sqrt(EI / (RHO_A * LENGTH**4))  # omega = b^2 OMEGA_UNIT
B1 = 1.8751040687119611
F1 = B1**2 * OMEGA_UNIT / (2.0 * math.pi)
TIP0 = 1e-3
WINDOW, DT, N_ELEMENTS = 0.06, 5e-6, 100
RKS = np.logspace(0, 6, 8)
RFTRUNCS = np.logspace(1, 3, 5)
PSD_POINTS, PSD_PADDING = 4096, 4
REST = 0.1 / F1


# ---------------------------------------------------------------- reference
def clamped_free_roots(b_max):
    """Roots b of 1 + cosh b cos b = 0 below b_max, by Newton from (n - 1/2) pi."""
    roots = []
    n = 1
    while True:
        b = (n - 0.5) * math.pi if n > 1 else B1
        for _ in range(20):
            f = math.cos(b) + 1.0 / math.cosh(b)
            df = -math.sin(b) - math.tanh(b) / math.cosh(b)
            b -= f / df
        if b > b_max:
            return np.array(roots)
        roots.append(b)
        n += 1


def residual_flexibility(n_kept):
    """Static tip flexibility of the clamped-free modes above the n_kept first (tip 2/sqrt(m))."""
    n = np.arange(n_kept + 1, n_kept + 1001, dtype=float)
    tail = np.sum(1.0 / ((n - 0.5) * math.pi) ** 4)
    tail += 1.0 / (3.0 * math.pi**4 * (n_kept + 1000.5) ** 3)  # the sum beyond, to 1e-13
    return 4.0 / MASS / OMEGA_UNIT**2 * tail


@njit(cache=True, fastmath=False)
def exact_tip(w, t, a, b, tau):
    u = 0.0
    for i in range(w.size):
        u += t[i] * (a[i] * math.cos(w[i] * tau) + b[i] * math.sin(w[i] * tau))
    return u


@njit(cache=True)
def find_exit(w, t, a, b, in_contact, step, tau_max):
    """First tau in (0, tau_max] where the tip crosses 0 out of the phase's side, or -1."""
    n = w.size
    rr = np.cos(w * step)
    ri = np.sin(w * step)
    zr = np.empty(n)
    zi = np.empty(n)
    sign = -1.0 if in_contact else 1.0
    first = min(1e-3 * step, tau_max)
    prev_tau = first if sign * exact_tip(w, t, a, b, first) > 0.0 else 0.0
    k = 0
    while True:
        if k % 512 == 0:  # anchor
            tau0 = k * step
            for i in range(n):
                c, s = math.cos(w[i] * tau0), math.sin(w[i] * tau0)
                zr[i] = t[i] * (a[i] * c + b[i] * s)
                zi[i] = t[i] * (a[i] * s - b[i] * c)
        u = 0.0
        for i in range(n):
            u += zr[i]
            xr = zr[i] * rr[i] - zi[i] * ri[i]
            zi[i] = zr[i] * ri[i] + zi[i] * rr[i]
            zr[i] = xr
        tau = k * step
        if tau >= tau_max:
            tau = tau_max
            u = exact_tip(w, t, a, b, tau)
        if k > 0 and sign * u < 0.0:
            lo, hi = prev_tau, tau
            flo = exact_tip(w, t, a, b, lo)
            fhi = u
            side = 0
            for _ in range(200):  # Illinois regula falsi
                m = (lo * fhi - hi * flo) / (fhi - flo)
                if not (lo < m < hi):
                    m = 0.5 * (lo + hi)
                fm = exact_tip(w, t, a, b, m)
                if (fm < 0.0) == (fhi < 0.0):
                    hi, fhi = m, fm
                    if side == -1:
                        flo *= 0.5
                    side = -1
                else:
                    lo, flo = m, fm
                    if side == 1:
                        fhi *= 0.5
                    side = 1
                if hi - lo < 1e-15 + 1e-14 * hi:
                    break
            return hi
        if tau >= tau_max:
            return -1.0
        if k > 0:
            prev_tau = tau
        k += 1


@njit(cache=True)
def sample_phase(w, t, a, b, tau0, dt, out):
    """out[k] = tip at tau0 + k dt, by rotation, anchored every 512 samples."""
    n = w.size
    rr = np.cos(w * dt)
    ri = np.sin(w * dt)
    zr = np.empty(n)
    zi = np.empty(n)
    for k in range(out.size):
        if k % 512 == 0:
            tau = tau0 + k * dt
            for i in range(n):
                c, s = math.cos(w[i] * tau), math.sin(w[i] * tau)
                zr[i] = t[i] * (a[i] * c + b[i] * s)
                zi[i] = t[i] * (a[i] * s - b[i] * c)
        u = 0.0
        for i in range(n):
            u += zr[i]
            xr = zr[i] * rr[i] - zi[i] * ri[i]
            zi[i] = zr[i] * ri[i] + zi[i] * rr[i]
            zr[i] = xr
        out[k] = u


def reference(r_k, r_fref, dt_out=None):
    """Tip and force on the output grid (its own unless dt_out), and the grid step."""
    k_s = r_k * K_BEND
    b_max = math.sqrt(2.0 * math.pi * r_fref * F1 / OMEGA_UNIT)
    roots = clamped_free_roots(b_max)
    w_free = roots**2 * OMEGA_UNIT
    t_free = np.full(roots.size, 2.0 / math.sqrt(MASS))
    r = residual_flexibility(roots.size)
    k_eff = k_s / (1.0 + k_s * r)
    lam, v = np.linalg.eigh(np.diag(w_free**2) + k_eff * np.outer(t_free, t_free))
    w_contact = np.sqrt(lam)
    t_contact = v.T @ t_free / (1.0 + k_s * r)
    t_min = 2.0 * math.pi / max(w_free.max(), w_contact.max())
    step = t_min / 16.0
    q = np.zeros(roots.size)
    q[0] = TIP0 / t_free[0]
    qd = np.zeros(roots.size)
    phases = [(0.0, False, q.copy(), qd / w_free)]  # (start, in contact, a, b)
    while True:
        start, contact, a, b = phases[-1]
        w, t = (w_contact, t_contact) if contact else (w_free, t_free)
        tau = find_exit(w, t, a, b, contact, step, WINDOW - start)
        if tau < 0.0:
            break
        qm = a * np.cos(w * tau) + b * np.sin(w * tau)
        qdm = w * (b * np.cos(w * tau) - a * np.sin(w * tau))
        if contact:
            qm, qdm = v @ qm, v @ qdm
            phases.append((start + tau, False, qm, qdm / w_free))
        else:
            qm, qdm = v.T @ qm, v.T @ qdm
            phases.append((start + tau, True, qm, qdm / w_contact))
    if dt_out is None:
        dt_out = WINDOW / math.ceil(WINDOW / (t_min / 8.0))
    n_out = int(math.floor(WINDOW / dt_out + 1e-9)) + 1
    tip = np.empty(n_out)
    force = np.zeros(n_out)
    starts = np.array([p[0] for p in phases] + [math.inf])
    i = 0
    for j, (start, contact, a, b) in enumerate(phases):
        end = n_out if math.isinf(starts[j + 1]) else min(n_out, math.ceil(starts[j + 1] / dt_out))
        while end < n_out and end * dt_out < starts[j + 1]:
            end += 1
        while end > i and (end - 1) * dt_out >= starts[j + 1]:
            end -= 1
        if end <= i:
            continue
        w, t = (w_contact, t_contact) if contact else (w_free, t_free)
        sample_phase(w, t, a, b, i * dt_out - start, dt_out, tip[i:end])
        if contact:
            force[i:end] = np.maximum(0.0, -k_s * tip[i:end])
        i = end
    return tip, force, dt_out, len(phases) - 1


# ---------------------------------------------------------------- numerical
def fe_modes():
    """Clamped-free Hermite beam: frequencies (rad/s) and the tip row of mass-normalized modes."""
    h = LENGTH / N_ELEMENTS
    ke = EI / h**3 * np.array([[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                               [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]])
    me = RHO_A * h / 420.0 * np.array(
        [[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
         [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]])
    n = 2 * (N_ELEMENTS + 1)
    k = np.zeros((n, n))
    m = np.zeros((n, n))
    for e in range(N_ELEMENTS):
        k[2 * e:2 * e + 4, 2 * e:2 * e + 4] += ke
        m[2 * e:2 * e + 4, 2 * e:2 * e + 4] += me
    k, m = k[2:, 2:], m[2:, 2:]
    chol = np.linalg.cholesky(m)
    inv = np.linalg.inv(chol)
    lam, y = np.linalg.eigh(inv @ k @ inv.T)
    phi = inv.T @ y
    return np.sqrt(lam), phi[-2, :]


@njit(cache=True)
def explicit_run(omega, phi, k_s, q0, dt, n_steps, tip, force):
    """Central differences on the modal model, the tip's penalty force (gap 0)."""
    n = omega.size
    q = q0.copy()
    qd = np.zeros(n)
    acc = np.empty(n)
    for step in range(n_steps + 1):
        u = 0.0
        for i in range(n):
            u += phi[i] * q[i]
        f = -k_s * u if u < 0.0 else 0.0
        tip[step] = u
        force[step] = f
        for i in range(n):
            a_new = -omega[i] * omega[i] * q[i] + phi[i] * f
            if step > 0:
                qd[i] += 0.5 * dt * (acc[i] + a_new)
            acc[i] = a_new
        if step == n_steps:
            break
        for i in range(n):
            q[i] += dt * qd[i] + 0.5 * dt * dt * acc[i]


# ---------------------------------------------------------------- scores
def psd(signal, dt):
    t = np.arange(PSD_POINTS) * (WINDOW / PSD_POINTS)
    x = np.interp(t, np.arange(signal.size) * dt, signal)
    w = 0.5 * (1.0 - np.cos(2.0 * math.pi * np.arange(PSD_POINTS) / PSD_POINTS))
    n_fft = 1 << (PSD_POINTS * PSD_PADDING - 1).bit_length()
    g = np.abs(np.fft.rfft(w * x, n_fft)) ** 2
    g[1:-1] *= 2.0
    return g / (PSD_POINTS / WINDOW * np.sum(w * w))


def err(g_num, g_ref):
    return np.max(np.abs(g_num - g_ref)) / max(g_num.max(), g_ref.max())


def first_shock_impulse(force, dt):
    """Trapezoidal impulse of the first group of contacts closer than REST, or 0."""
    on = np.flatnonzero(force > 0.0)
    if on.size == 0:
        return 0.0
    gaps = np.flatnonzero(np.diff(on) * dt > REST)
    last = on[gaps[0]] if gaps.size else on[-1]
    lo, hi = max(on[0] - 1, 0), min(last + 1, force.size - 1)
    return np.trapz(force[lo:hi + 1], dx=dt)


def srf(i_num, i_ref):
    return min(i_num, i_ref) / max(i_num, i_ref) if max(i_num, i_ref) > 0.0 else 1.0


# ---------------------------------------------------------------- the grid
def load_compiled():
    """Numba's compiled functions loaded (from its cache, or compiled) on a tiny problem, so that
    the script's own time counts its arithmetic, not the loading."""
    reference(1.0, 10.0)
    explicit_run(np.ones(1), np.ones(1), 1.0, np.zeros(1), DT, 1, np.empty(2), np.empty(2))


def main():
    load_compiled()
    start, start_cpu = time.perf_counter(), time.process_time()
    db = sqlite3.connect(sys.argv[1]) if len(sys.argv) > 1 else None
    if db:
        db.execute("create table if not exists scores (rk real, rftrunc real, n_modes integer, "
                   "err real, srf real, ref_difference real, transitions integer)")
    omega_fe, phi_fe = fe_modes()
    n_steps = int(round(WINDOW / DT))
    cpu_ref = cpu_points = 0.0
    for r_k in RKS:
        c0 = time.process_time()
        r_fref = max(2000.0, 30.0 * math.sqrt(r_k))
        tip_ref, force_ref, dt_ref, transitions = reference(r_k, r_fref)
        tip_check, _, _, _ = reference(r_k, r_fref / 3.0, dt_ref)
        difference = np.max(np.abs(tip_ref - tip_check)) / np.max(np.abs(tip_ref))
        g_ref = psd(tip_ref, dt_ref)
        i_ref = first_shock_impulse(force_ref, dt_ref)
        c1 = time.process_time()
        cpu_ref += c1 - c0
        for r_ftrunc in RFTRUNCS:
            keep = omega_fe < 2.0 * math.pi * r_ftrunc * F1
            omega, phi = omega_fe[keep], phi_fe[keep]
            q0 = np.zeros(omega.size)
            q0[0] = TIP0 / phi[0]
            tip = np.empty(n_steps + 1)
            force = np.empty(n_steps + 1)
            explicit_run(omega, phi, r_k * K_BEND, q0, DT, n_steps, tip, force)
            e = err(psd(tip, DT), g_ref)
            s = srf(first_shock_impulse(force, DT), i_ref)
            if db:
                db.execute("insert into scores values (?, ?, ?, ?, ?, ?, ?)",
                           (r_k, r_ftrunc, int(omega.size), e, s, difference, transitions))
            print(f"R_k {r_k:9.4g}  R_ftrunc {r_ftrunc:6.4g}  modes {omega.size:3d}  Err {e:.3f}"
                  f"  SRf {s:.3f}  reference {r_fref:.0f} f1 ({transitions} transitions, "
                  f"check {difference:.1e})")
        cpu_points += time.process_time() - c1
    if db:
        db.commit()
        db.close()
    print(f"grid: {time.perf_counter() - start:.3f} s wall, {time.process_time() - start_cpu:.3f} s "
          f"CPU inside the script; CPU references {cpu_ref:.3f} s, points {cpu_points:.3f} s")


if __name__ == "__main__":
    main()
