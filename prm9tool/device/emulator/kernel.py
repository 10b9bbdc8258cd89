"""The 200 µs control loop and the plant, as one lean generator.

Hot-loop design (docs/PERFORMANCE.md): the generator keeps every state variable in local
variables of its frame across batches, so a batch costs no attribute look-ups and no
allocation per cycle; :class:`~.loopstate.LoopState` is its mailbox to the firmware. The loop
is deliberately one long function: splitting it into per-block functions would add a Python
call (~50 ns each, a dozen per cycle) to every 200 µs cycle.

Units inside the loop: process values in normalized counts (±16384 = ±100 %), currents in mA,
voltages in V, forces in N, spool travel in m, actuator position as a fraction 0…1 of stroke.
"""

from __future__ import annotations

import math
from bisect import bisect_right
from collections.abc import Generator

from prm9tool.device.emulator.constants import FULL
from prm9tool.device.emulator.loopstate import MODE_ACTIVE, MODE_OFF, LoopState


def control_loop(s: LoopState) -> Generator[None, int, None]:
    """Run ``n`` cycles per ``send(n)``; ``send(0)`` writes every measuring point back.

    After a batch only what the firmware's 1 ms task needs is written back (coil currents and
    PWM duties, LVDT loop current, control deviation); inputs are re-read only when
    ``inputs_version`` changed, coefficients only when ``version`` changed.
    """
    sin = math.sin
    bis = bisect_right
    two_pi = 2.0 * math.pi
    full = FULL  # 100 %: the controllers' and the sensor path's upper limit
    # --- dynamic state (kept in this frame) ------------------------------------------------
    r = 0.0  # ramp output (demand value)
    x = s.spool_m
    v = s.spool_v
    act = s.actuator
    ia = ib = 0.0  # coil currents, mA
    f = 0.0  # magnetic force, N
    ia_i = ib_i = 0.0  # current-controller integrators, V
    p_int = p_d = p_prev = 0.0  # position PIDT1
    q_int = q_d = q_prev = 0.0  # process PIDT1
    ph = 0.0  # dither phase, rad
    cap_count = 0
    last_mode = MODE_OFF
    w = u = ca = cb = ka = kb = da = db = xm = pe = 0.0
    s0 = s1 = s2 = s3 = pv = dev = dg = 0.0
    n = yield
    while True:
        c = s.coefficients
        version = s.version
        e04 = c["e04_plant"]  # external sensor and hydraulic load exist (E04 variant)
        process_on = c["process_loop"]  # the process PIDT1 closes the loop (E04, mode 4)
        if not process_on:
            dev = dg = 0.0
        coils = c["coils"]  # "AB", "A" or "B"
        two = coils == "AB"
        only_b = coils == "B"
        rpu, rpd, rnu, rnd = c["ramp_steps"]
        pkp, pki, pkd, pt1 = c["position_pid"]
        qkp, qki, qkd, qt1 = c["process_pid"]
        out_lo = 0.0 if not two else -full
        kcur = c["ma_per_count"]
        lim_a, lim_b = c["limits_ma"]
        damp, dph = c["dither"]
        ckp, cki, rff_a, rff_b = c["current_pi"]
        vmax_i = c["max_current_v"]
        kf, ks, cd, fc, fs, im, h, nsub, xmax, flag = c["mechanics"]
        kx, lvdt_q, lvdt_lo, lvdt_ma_k, lvdt_sat = c["lvdt"]
        s_a, s_b, s_q, s_o, sinv, soffs, sgain, slin = c["sensor"]
        sl_x, sl_k, sl_b = c["sensor_curve"]
        gp, op, gn, on_ = c["deviation_gain"]
        act_k, overlap, act_ret = c["actuator"]
        aa_c, ba_c, ab_c, bb_c = c["coil_discrete"]
        subs = range(nsub)
        inputs_version = -1
        while s.version == version:
            if s.inputs_version != inputs_version:
                inputs_version = s.inputs_version
                mode = s.mode
                tgt = s.target
                vs = s.supply_v
                inv_vs = 1.0 / vs if vs > 0.5 else 2.0
                open_a, open_b = s.coil_open
                short_a, short_b = s.coil_short
                on_a, on_b = s.stage_on
                aa = 0.0 if open_a else aa_c
                ba = 0.0 if open_a else ba_c
                ab = 0.0 if open_b else ab_c
                bb = 0.0 if open_b else bb_c
                lvdt_break = s.lvdt_break
                plant_sensor = s.sensor_from_plant
                s_static = s.sensor_static
                s_broken = s.sensor_break_value
                if s_broken is not None:
                    plant_sensor = False
                    s_static = s_broken
                active = mode == MODE_ACTIVE
                process = process_on and active
                if active and last_mode != MODE_ACTIVE:
                    r = pv if process else xm  # the ramp starts where the valve is (bumpless)
                last_mode = mode
                if mode == MODE_OFF:
                    ia_i = ib_i = p_int = p_d = p_prev = 0.0
                if not process:
                    q_int = q_d = q_prev = 0.0
                stat = s.static_signals
                cap = s.capture
                if cap is not None:
                    cap_ext, cap_get, cap_dec = cap[:3]
                temp10 = s.temperature_c * 10.0
            if n == 0:
                # --- flush: every measuring point and the plant state -------------------
                s.signals = (
                    stat[0],
                    stat[1],
                    stat[2],
                    stat[3],
                    r,
                    r,
                    pv,
                    dg,
                    w,
                    xm,
                    pe,
                    u,
                    ca,
                    cb,
                    ia,
                    ib,
                    da * 10000.0,
                    db * 10000.0,
                    vs * 1000.0,
                    temp10,
                    s0,
                )
                s.spool_m = x
                s.spool_v = v
                s.actuator = act
                s.sensor_chain = (s0, s1, s2, s3, pv)
            for _ in range(n):
                # --- demand value generator: four ramps ---------------------------------
                if r != tgt:
                    if r > 0.0 or (r == 0.0 and tgt > 0.0):
                        if tgt > r:
                            r += rpu
                            if r > tgt:
                                r = tgt
                        else:
                            r -= rpd
                            lo = tgt if tgt > 0.0 else 0.0
                            if r < lo:
                                r = lo
                    elif tgt < r:
                        r -= rnu
                        if r < tgt:
                            r = tgt
                    else:
                        r += rnd
                        hi = tgt if tgt < 0.0 else 0.0
                        if r > hi:
                            r = hi
                # --- spool position measurement (LVDT, 12 bit) --------------------------
                if lvdt_break:
                    xm = lvdt_lo
                else:
                    xm = round(x * kx) * lvdt_q
                # --- external sensor (E04) and process controller (E04 in mode 4) ---------
                if e04:
                    if plant_sensor:
                        s0 = round(act * s_a + s_b) * s_q + s_o
                    else:
                        s0 = s_static
                    s1 = -s0 if sinv else s0
                    s2 = s1 + soffs
                    s3 = s2 * sgain
                    if s3 > full:
                        s3 = full
                    elif s3 < -full:
                        s3 = -full
                    if slin:
                        i = bis(sl_x, s3)
                        pv = sl_b[i] + sl_k[i] * s3
                    else:
                        pv = s3
                    if process_on:
                        dev = r - pv
                        if dev > 0.0:
                            dg = dev * gp + op
                        elif dev < 0.0:
                            dg = dev * gn - on_
                        else:
                            dg = 0.0
                if process:
                    q_int += qki * dg
                    if q_int > full:
                        q_int = full
                    elif q_int < out_lo:
                        q_int = out_lo
                    q_d = qt1 * q_d + qkd * (dg - q_prev)
                    q_prev = dg
                    w = qkp * dg + q_int + q_d
                    if w > full:
                        w = full
                    elif w < out_lo:
                        w = out_lo
                elif active:
                    w = r
                else:
                    w = 0.0
                # --- position PIDT1 -------------------------------------------------------
                pe = w - xm
                if mode:
                    p_int += pki * pe
                    if p_int > full:
                        p_int = full
                    elif p_int < out_lo:
                        p_int = out_lo
                    p_d = pt1 * p_d + pkd * (pe - p_prev)
                    p_prev = pe
                    u = pkp * pe + p_int + p_d
                    if u > full:
                        u = full
                    elif u < out_lo:
                        u = out_lo
                else:
                    u = 0.0
                # --- current limiter per coil and dither ---------------------------------
                if u > 0.0:
                    if only_b:
                        ca = 0.0
                        cb = u * kcur
                        if cb > lim_b:
                            cb = lim_b
                    else:
                        cb = 0.0
                        ca = u * kcur
                        if ca > lim_a:
                            ca = lim_a
                elif u < 0.0:
                    ca = 0.0
                    cb = -u * kcur
                    if cb > lim_b:
                        cb = lim_b
                else:
                    ca = cb = 0.0
                ph += dph
                if ph > two_pi:
                    ph -= two_pi
                dv = damp * sin(ph)
                if two:
                    # The dither rides on the signed current demand A − B; the sign says
                    # which solenoid carries it, so through the null it passes from coil to
                    # coil and the force stays demand plus a whole sine (docs/emulator.md).
                    ka = ca - cb + dv
                    if ka < 0.0:
                        kb = -ka
                        ka = 0.0
                    else:
                        kb = 0.0
                else:
                    ka = ca + dv if ca > 0.0 else 0.0
                    if ka < 0.0:
                        ka = 0.0
                    kb = cb + dv if cb > 0.0 else 0.0
                    if kb < 0.0:
                        kb = 0.0
                # --- current controllers, PWM duty, solenoid R-L circuits -----------------
                # A shorted stage puts the supply on the coil whatever the duty, until the
                # firmware opens the stage's safety switch (on_a / on_b False).
                # Fast decay: a stage reverses the coil voltage (duty −100…100 %) while
                # current flows; a solenoid current does not reverse (the bridge's diodes
                # end it at 0). At 0 mA demand the controller quenches the coil with the
                # full reverse voltage and clears its integrator.
                if on_a and mode:
                    if ka > 0.0:
                        err = ka - ia
                        ia_i += cki * err
                        if ia_i > vmax_i:
                            ia_i = vmax_i
                        elif ia_i < -vmax_i:
                            ia_i = -vmax_i
                        da = (rff_a * ka + ckp * err + ia_i) * inv_vs
                        if da > 1.0:
                            da = 1.0
                        elif da < -1.0:
                            da = -1.0
                    else:
                        ia_i = 0.0
                        da = -1.0 if ia > 0.0 else 0.0
                    ia = ia * aa + ba * (vs if short_a else da * vs)
                    if ia < 0.0:
                        ia = 0.0
                else:
                    da = 0.0
                    ia = ia * aa + ba * vs if short_a and on_a else ia * aa
                if on_b and mode:
                    if kb > 0.0:
                        err = kb - ib
                        ib_i += cki * err
                        if ib_i > vmax_i:
                            ib_i = vmax_i
                        elif ib_i < -vmax_i:
                            ib_i = -vmax_i
                        db = (rff_b * kb + ckp * err + ib_i) * inv_vs
                        if db > 1.0:
                            db = 1.0
                        elif db < -1.0:
                            db = -1.0
                    else:
                        ib_i = 0.0
                        db = -1.0 if ib > 0.0 else 0.0
                    ib = ib * ab + bb * (vs if short_b else db * vs)
                    if ib < 0.0:
                        ib = 0.0
                else:
                    db = 0.0
                    ib = ib * ab + bb * vs if short_b and on_b else ib * ab
                # --- spool: force, spring, damping, friction, stroke limits ---------------
                if two:
                    f += (kf * (ia - ib) - f) * flag
                elif only_b:
                    f += (kf * ib - f) * flag
                else:
                    f += (kf * ia - f) * flag
                for _k in subs:
                    fn = f - ks * x - cd * v
                    if v > 0.0:
                        nv = v + (fn - fc) * im
                        if nv < 0.0:
                            nv = 0.0
                    elif v < 0.0:
                        nv = v + (fn + fc) * im
                        if nv > 0.0:
                            nv = 0.0
                    elif fn > fs:
                        nv = (fn - fc) * im
                    elif fn < -fs:
                        nv = (fn + fc) * im
                    else:
                        nv = 0.0
                    v = nv
                    x += v * h
                    if x > xmax:
                        x = xmax
                        if v > 0.0:
                            v = 0.0
                    elif x < -xmax:
                        x = -xmax
                        if v < 0.0:
                            v = 0.0
                # --- hydraulic actuator (E04 load) ----------------------------------------
                if e04:
                    opening = x
                    if overlap:
                        if opening > overlap:
                            opening -= overlap
                        elif opening < -overlap:
                            opening += overlap
                        else:
                            opening = 0.0
                    act += opening * act_k - act * act_ret
                    if act > 1.0:
                        act = 1.0
                    elif act < 0.0:
                        act = 0.0
                # --- capture -------------------------------------------------------------
                # The selection is only known at run time, so the values go through a tuple
                # and an itemgetter: ~0.4 µs per captured cycle against ~0.2 µs for a
                # hard-coded triple (measured); only a loop generated per selection could
                # save the difference (~5 % of a cycle), which is not worth the complexity.
                if cap is not None:
                    cap_count -= 1
                    if cap_count <= 0:
                        cap_count = cap_dec
                        cap_ext(
                            cap_get(
                                (
                                    stat[0],
                                    stat[1],
                                    stat[2],
                                    stat[3],
                                    r,
                                    r,
                                    pv,
                                    dg,
                                    w,
                                    xm,
                                    pe,
                                    u,
                                    ca,
                                    cb,
                                    ia,
                                    ib,
                                    da * 10000.0,
                                    db * 10000.0,
                                    vs * 1000.0,
                                    temp10,
                                    s0,
                                )
                            )
                        )
            # --- what the 1 ms task needs; the rest on a flush (send(0)) --------------------
            s.ctrl_dev = dev if process_on else r - xm
            s.current_ma = (ia, ib)
            s.duty = (da, db)
            if lvdt_break:
                s.lvdt_ma = 0.0  # a cut wire carries no loop current
            else:
                lvdt_ma = 12.0 + x * lvdt_ma_k
                s.lvdt_ma = lvdt_ma if lvdt_ma > lvdt_sat else lvdt_sat
            n = yield
