/* The emulated valve's 200 us control loop, compiled (docs/emulator.md "Compiled kernel").
 *
 * A line-by-line transcription of prm9tool/device/emulator/kernel.py (the reference): the same
 * operations on IEEE doubles in the same order. Built without fast-math and with
 * -ffp-contract=off (setup.py) so no multiply-add is fused: every result is rounded exactly as
 * CPython rounds it, and the two kernels give bit-identical values
 * (tests/test_emulator_kernels.py).
 *
 * State, coefficients, inputs and tick parameters are flat arrays of doubles laid out by the
 * enums below; prm9tool/device/emulator/ckernel.py fills them in the same order. run() works
 * on them without the GIL.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#ifdef __MINGW32__
/* mingw-w64 links a sin() of its own (libmingwex: x87 long double, then rounded), up to 10 ulp
 * from the C runtime's; CPython's math.sin is the Universal C runtime's (ucrtbase.dll, loaded
 * with python3XX.dll), so this kernel calls that one, looked up at import. MSVC links the
 * ucrt's sin directly. (docs/executable.md "The emulator's kernel on Windows") */
#define WIN32_LEAN_AND_MEAN
#include <windows.h>
static double (*crt_sin)(double) = sin;
static void use_crt_sin(void)
{
    HMODULE ucrt = GetModuleHandleA("ucrtbase.dll");
    FARPROC found = ucrt ? GetProcAddress(ucrt, "sin") : NULL;
    if (found) crt_sin = (double (*)(double))(void (*)(void))found;
}
#define sin(x) crt_sin(x)
#else
#define use_crt_sin() ((void)0)
#endif

enum { /* dynamic state */
    S_R, S_X, S_V, S_ACT, S_IA, S_IB, S_F, S_IA_I, S_IB_I, S_P_INT, S_P_D, S_P_PREV,
    S_Q_INT, S_Q_D, S_Q_PREV, S_PH, S_CAP_COUNT, S_W, S_U, S_CA, S_CB, S_KA, S_KB, S_DA, S_DB,
    S_XM, S_PE, S_S0, S_S1, S_S2, S_S3, S_PV, S_DEV, S_DG, S_COUNT
};
enum { /* coefficients */
    C_E04, C_PROCESS_ON, C_TWO, C_ONLY_B, C_RPU, C_RPD, C_RNU, C_RND, C_PKP, C_PKI, C_PKD, C_PT1,
    C_QKP, C_QKI, C_QKD, C_QT1, C_OUT_LO, C_KCUR, C_LIM_A, C_LIM_B, C_DAMP, C_DPH, C_CKP, C_CKI,
    C_RFF_A, C_RFF_B, C_VMAX_I, C_KF, C_KS, C_CD, C_FC, C_FS, C_IM, C_H, C_NSUB, C_XMAX, C_FLAG,
    C_KX, C_LVDT_Q, C_LVDT_LO, C_LVDT_MA_K, C_LVDT_SAT, C_S_A, C_S_B, C_S_Q, C_S_O, C_SINV,
    C_SOFFS, C_SGAIN, C_SLIN, C_GP, C_OP, C_GN, C_ON, C_ACT_K, C_OVERLAP, C_ACT_RET, C_FULL, C_SL_N,
    C_SL_X, C_SL_K = C_SL_X + 16, C_SL_B = C_SL_K + 17, C_COUNT = C_SL_B + 17
};
enum { /* per-batch inputs */
    I_MODE, I_TGT, I_VS, I_INV_VS, I_SHORT_A, I_SHORT_B, I_ON_A, I_ON_B, I_AA, I_BA, I_AB, I_BB,
    I_LVDT_BREAK, I_PLANT_SENSOR, I_S_STATIC, I_ACTIVE, I_PROCESS, I_STAT0, I_STAT1, I_STAT2,
    I_STAT3, I_TEMP10, I_CAP_ON, I_CAP_DEC, I_CAP0, I_CAP1, I_CAP2, I_COUNT
};
enum { /* the 1 ms task's no-op test (see fasttick.py) */
    T_CYCLE_S, T_CYCLES0, T_BOOTING, T_BOOT_S, T_MAX_TICKS, T_OVR_ON, T_OVR_LAST, T_OVR_TIMEOUT,
    T_EVAL, T_REF_MASK, T_STATIC_BITS, T_OVERCURRENT_MA, T_TEMP_ALARM, T_MON_THR,
    T_STATE_ACTIVE, T_PRESENT_MON, T_SUPPLY, T_COIL_OPEN_A, T_COIL_OPEN_B, T_HAS_A, T_HAS_B,
    T_OC_HOLD_A, T_OC_HOLD_B, T_LOOP_BREAK_MA, T_OPEN_MIN_V, T_OPEN_MA,
    /* the thermal model (thermal.step every THERMAL_TICKS); T_RISE and T_TEMPERATURE in/out */
    T_THERMAL, T_TICKS0, T_THERMAL_TICKS, T_DT, T_R_COIL, T_LOSS_W, T_K_PER_W, T_TAU_S,
    T_AMBIENT, T_COIL_T, T_COIL_REFRESH_K, T_RISE, T_TEMPERATURE, T_WARN_C, T_WARN_OFF_C,
    T_WARNING, T_TEMP_LIMIT, T_N_DEADLINES, T_DEADLINES, T_COUNT = T_DEADLINES + 3 * 16
};
enum { /* bits of the raw fault conditions (detect.conditions order) */
    B_COIL_A_OPEN = 1 << 2, B_COIL_B_OPEN = 1 << 3, B_POSITION = 1 << 4,
    B_COIL_A_OC = 1 << 5, B_COIL_B_OC = 1 << 6, B_TEMPERATURE = 1 << 8, B_MONITORING = 1 << 9
};
#define TICK_CYCLES 5
/* Batches shorter than this keep the GIL: a few cycles take less than a microsecond, while
 * handing the GIL over makes the caller queue behind every other thread's Python (several
 * valves stepped 1 ms at a time by their USB links). */
#define RELEASE_GIL_CYCLES 100
#define TWO_PI 6.283185307179586 /* 2.0 * math.pi */

/* Python's round(v) returns an int, which has no negative zero: "+ 0.0" turns -0.0 into 0.0. */
static inline double py_round(double v) { return rint(v) + 0.0; }

/* not "signal": <signal.h>'s function of that name clashes (it is included under mingw-w64) */
static inline double captured_signal(const double *s, const double *in, const double *stat, int k)
{
    switch (k) {
    case 0: case 1: case 2: case 3: return stat[k];
    case 4: case 5: return s[S_R];
    case 6: return s[S_PV];
    case 7: return s[S_DG];
    case 8: return s[S_W];
    case 9: return s[S_XM];
    case 10: return s[S_PE];
    case 11: return s[S_U];
    case 12: return s[S_CA];
    case 13: return s[S_CB];
    case 14: return s[S_IA];
    case 15: return s[S_IB];
    case 16: return s[S_DA] * 10000.0;
    case 17: return s[S_DB] * 10000.0;
    case 18: return in[I_VS] * 1000.0;
    case 19: return in[I_TEMP10];
    default: return s[S_S0];
    }
}

/* Run n cycles; captured samples go to cap (3 doubles each). Returns the number of samples. */
static Py_ssize_t cycles(double *st, const double *c, const double *in, long n, double *cap,
                         const double *prog)
{
    double r = st[S_R], x = st[S_X], v = st[S_V], act = st[S_ACT], ia = st[S_IA], ib = st[S_IB];
    double f = st[S_F], ia_i = st[S_IA_I], ib_i = st[S_IB_I];
    double p_int = st[S_P_INT], p_d = st[S_P_D], p_prev = st[S_P_PREV];
    double q_int = st[S_Q_INT], q_d = st[S_Q_D], q_prev = st[S_Q_PREV], ph = st[S_PH];
    long cap_count = (long)st[S_CAP_COUNT];
    double w = st[S_W], u = st[S_U], ca = st[S_CA], cb = st[S_CB], ka = st[S_KA], kb = st[S_KB];
    double da = st[S_DA], db = st[S_DB], xm = st[S_XM], pe = st[S_PE];
    double s0 = st[S_S0], s1 = st[S_S1], s2 = st[S_S2], s3 = st[S_S3], pv = st[S_PV];
    double dev = st[S_DEV], dg = st[S_DG];
    const int e04 = c[C_E04] != 0.0, process_on = c[C_PROCESS_ON] != 0.0;
    const int two = c[C_TWO] != 0.0, only_b = c[C_ONLY_B] != 0.0;
    const double rpu = c[C_RPU], rpd = c[C_RPD], rnu = c[C_RNU], rnd = c[C_RND];
    const double pkp = c[C_PKP], pki = c[C_PKI], pkd = c[C_PKD], pt1 = c[C_PT1];
    const double qkp = c[C_QKP], qki = c[C_QKI], qkd = c[C_QKD], qt1 = c[C_QT1];
    const double full = c[C_FULL]; /* 100 %: the controllers' and the sensor path's limit */
    const double out_lo = c[C_OUT_LO], kcur = c[C_KCUR], lim_a = c[C_LIM_A], lim_b = c[C_LIM_B];
    const double damp = c[C_DAMP], dph = c[C_DPH], ckp = c[C_CKP], cki = c[C_CKI];
    const double rff_a = c[C_RFF_A], rff_b = c[C_RFF_B], vmax_i = c[C_VMAX_I];
    const double kf = c[C_KF], ks = c[C_KS], cd = c[C_CD], fc = c[C_FC], fs = c[C_FS];
    const double im = c[C_IM], h = c[C_H], xmax = c[C_XMAX], flag = c[C_FLAG];
    const long nsub = (long)c[C_NSUB];
    const double kx = c[C_KX], lvdt_q = c[C_LVDT_Q], lvdt_lo = c[C_LVDT_LO];
    const double s_a = c[C_S_A], s_b = c[C_S_B], s_q = c[C_S_Q], s_o = c[C_S_O];
    const int sinv = c[C_SINV] != 0.0, slin = c[C_SLIN] != 0.0;
    const double soffs = c[C_SOFFS], sgain = c[C_SGAIN];
    const double gp = c[C_GP], op = c[C_OP], gn = c[C_GN], on_ = c[C_ON];
    const double act_k = c[C_ACT_K], overlap = c[C_OVERLAP], act_ret = c[C_ACT_RET];
    const int sl_n = (int)c[C_SL_N];
    const double *sl_x = c + C_SL_X, *sl_k = c + C_SL_K, *sl_b = c + C_SL_B;
    const long mode = (long)in[I_MODE];
    double tgt = in[I_TGT];
    const double vs = in[I_VS], inv_vs = in[I_INV_VS];
    double stat[4] = {in[I_STAT0], in[I_STAT1], in[I_STAT2], in[I_STAT3]};
    const int short_a = in[I_SHORT_A] != 0.0, short_b = in[I_SHORT_B] != 0.0;
    const int on_a = in[I_ON_A] != 0.0, on_b = in[I_ON_B] != 0.0;
    const double aa = in[I_AA], ba = in[I_BA], ab = in[I_AB], bb = in[I_BB];
    const int lvdt_break = in[I_LVDT_BREAK] != 0.0, plant_sensor = in[I_PLANT_SENSOR] != 0.0;
    const double s_static = in[I_S_STATIC];
    const int active = in[I_ACTIVE] != 0.0, process = in[I_PROCESS] != 0.0;
    const int cap_on = in[I_CAP_ON] != 0.0;
    const long cap_dec = (long)in[I_CAP_DEC];
    const int cap0 = (int)in[I_CAP0], cap1 = (int)in[I_CAP1], cap2 = (int)in[I_CAP2];
    Py_ssize_t samples = 0;

    for (long k = 0; k < n; k++) {
        if (prog) { /* the generator's waveform: this cycle's static setpoint chain */
            const double *p = prog + 4 * k;
            stat[0] = p[0]; stat[1] = p[1]; stat[2] = p[2]; stat[3] = p[3];
            tgt = p[3];
        }
        /* demand value generator: four ramps */
        if (r != tgt) {
            if (r > 0.0 || (r == 0.0 && tgt > 0.0)) {
                if (tgt > r) {
                    r += rpu;
                    if (r > tgt) r = tgt;
                } else {
                    r -= rpd;
                    double lo = tgt > 0.0 ? tgt : 0.0;
                    if (r < lo) r = lo;
                }
            } else if (tgt < r) {
                r -= rnu;
                if (r < tgt) r = tgt;
            } else {
                r += rnd;
                double hi = tgt < 0.0 ? tgt : 0.0;
                if (r > hi) r = hi;
            }
        }
        /* spool position measurement */
        xm = lvdt_break ? lvdt_lo : py_round(x * kx) * lvdt_q;
        /* external sensor and process controller */
        if (e04) {
            s0 = plant_sensor ? py_round(act * s_a + s_b) * s_q + s_o : s_static;
            s1 = sinv ? -s0 : s0;
            s2 = s1 + soffs;
            s3 = s2 * sgain;
            if (s3 > full) s3 = full;
            else if (s3 < -full) s3 = -full;
            if (slin) {
                int i = 0;
                while (i < sl_n && sl_x[i] <= s3) i++; /* bisect_right */
                pv = sl_b[i] + sl_k[i] * s3;
            } else {
                pv = s3;
            }
            if (process_on) {
                dev = r - pv;
                if (dev > 0.0) dg = dev * gp + op;
                else if (dev < 0.0) dg = dev * gn - on_;
                else dg = 0.0;
            }
        }
        if (process) {
            q_int += qki * dg;
            if (q_int > full) q_int = full;
            else if (q_int < out_lo) q_int = out_lo;
            q_d = qt1 * q_d + qkd * (dg - q_prev);
            q_prev = dg;
            w = qkp * dg + q_int + q_d;
            if (w > full) w = full;
            else if (w < out_lo) w = out_lo;
        } else if (active) {
            w = r;
        } else {
            w = 0.0;
        }
        /* position PIDT1 */
        pe = w - xm;
        if (mode) {
            p_int += pki * pe;
            if (p_int > full) p_int = full;
            else if (p_int < out_lo) p_int = out_lo;
            p_d = pt1 * p_d + pkd * (pe - p_prev);
            p_prev = pe;
            u = pkp * pe + p_int + p_d;
            if (u > full) u = full;
            else if (u < out_lo) u = out_lo;
        } else {
            u = 0.0;
        }
        /* current limiter per coil and dither */
        if (u > 0.0) {
            if (only_b) {
                ca = 0.0;
                cb = u * kcur;
                if (cb > lim_b) cb = lim_b;
            } else {
                cb = 0.0;
                ca = u * kcur;
                if (ca > lim_a) ca = lim_a;
            }
        } else if (u < 0.0) {
            ca = 0.0;
            cb = -u * kcur;
            if (cb > lim_b) cb = lim_b;
        } else {
            ca = cb = 0.0;
        }
        ph += dph;
        if (ph > TWO_PI) ph -= TWO_PI;
        double dv = damp * sin(ph);
        if (two) {
            /* the dither rides on the signed demand A - B; its sign picks the solenoid */
            ka = ca - cb + dv;
            if (ka < 0.0) {
                kb = -ka;
                ka = 0.0;
            } else {
                kb = 0.0;
            }
        } else {
            ka = ca > 0.0 ? ca + dv : 0.0;
            if (ka < 0.0) ka = 0.0;
            kb = cb > 0.0 ? cb + dv : 0.0;
            if (kb < 0.0) kb = 0.0;
        }
        /* current controllers, PWM duty (-1..1: fast decay), solenoid R-L circuits; at 0 mA
         * demand the coil is quenched with the full reverse voltage and the integrator cleared */
        if (on_a && mode) {
            if (ka > 0.0) {
                double err = ka - ia;
                ia_i += cki * err;
                if (ia_i > vmax_i) ia_i = vmax_i;
                else if (ia_i < -vmax_i) ia_i = -vmax_i;
                da = (rff_a * ka + ckp * err + ia_i) * inv_vs;
                if (da > 1.0) da = 1.0;
                else if (da < -1.0) da = -1.0;
            } else {
                ia_i = 0.0;
                da = ia > 0.0 ? -1.0 : 0.0;
            }
            ia = ia * aa + ba * (short_a ? vs : da * vs);
            if (ia < 0.0) ia = 0.0;
        } else {
            da = 0.0;
            ia = (short_a && on_a) ? ia * aa + ba * vs : ia * aa;
        }
        if (on_b && mode) {
            if (kb > 0.0) {
                double err = kb - ib;
                ib_i += cki * err;
                if (ib_i > vmax_i) ib_i = vmax_i;
                else if (ib_i < -vmax_i) ib_i = -vmax_i;
                db = (rff_b * kb + ckp * err + ib_i) * inv_vs;
                if (db > 1.0) db = 1.0;
                else if (db < -1.0) db = -1.0;
            } else {
                ib_i = 0.0;
                db = ib > 0.0 ? -1.0 : 0.0;
            }
            ib = ib * ab + bb * (short_b ? vs : db * vs);
            if (ib < 0.0) ib = 0.0;
        } else {
            db = 0.0;
            ib = (short_b && on_b) ? ib * ab + bb * vs : ib * ab;
        }
        /* spool: force, spring, damping, friction, stroke limits */
        if (two) f += (kf * (ia - ib) - f) * flag;
        else if (only_b) f += (kf * ib - f) * flag;
        else f += (kf * ia - f) * flag;
        for (long j = 0; j < nsub; j++) {
            double fn = f - ks * x - cd * v, nv;
            if (v > 0.0) {
                nv = v + (fn - fc) * im;
                if (nv < 0.0) nv = 0.0;
            } else if (v < 0.0) {
                nv = v + (fn + fc) * im;
                if (nv > 0.0) nv = 0.0;
            } else if (fn > fs) {
                nv = (fn - fc) * im;
            } else if (fn < -fs) {
                nv = (fn + fc) * im;
            } else {
                nv = 0.0;
            }
            v = nv;
            x += v * h;
            if (x > xmax) {
                x = xmax;
                if (v > 0.0) v = 0.0;
            } else if (x < -xmax) {
                x = -xmax;
                if (v < 0.0) v = 0.0;
            }
        }
        /* hydraulic actuator (E04 load) */
        if (e04) {
            double opening = x;
            if (overlap != 0.0) {
                if (opening > overlap) opening -= overlap;
                else if (opening < -overlap) opening += overlap;
                else opening = 0.0;
            }
            act += opening * act_k - act * act_ret;
            if (act > 1.0) act = 1.0;
            else if (act < 0.0) act = 0.0;
        }
        /* capture */
        if (cap_on) {
            cap_count -= 1;
            if (cap_count <= 0) {
                cap_count = cap_dec;
                st[S_R] = r; st[S_PV] = pv; st[S_DG] = dg; st[S_W] = w; st[S_XM] = xm;
                st[S_PE] = pe; st[S_U] = u; st[S_CA] = ca; st[S_CB] = cb; st[S_IA] = ia;
                st[S_IB] = ib; st[S_DA] = da; st[S_DB] = db; st[S_S0] = s0;
                double *row = cap + 3 * samples++;
                row[0] = captured_signal(st, in, stat, cap0);
                row[1] = captured_signal(st, in, stat, cap1);
                row[2] = captured_signal(st, in, stat, cap2);
            }
        }
    }
    st[S_R] = r; st[S_X] = x; st[S_V] = v; st[S_ACT] = act; st[S_IA] = ia; st[S_IB] = ib;
    st[S_F] = f; st[S_IA_I] = ia_i; st[S_IB_I] = ib_i;
    st[S_P_INT] = p_int; st[S_P_D] = p_d; st[S_P_PREV] = p_prev;
    st[S_Q_INT] = q_int; st[S_Q_D] = q_d; st[S_Q_PREV] = q_prev; st[S_PH] = ph;
    st[S_CAP_COUNT] = (double)cap_count;
    st[S_W] = w; st[S_U] = u; st[S_CA] = ca; st[S_CB] = cb; st[S_KA] = ka; st[S_KB] = kb;
    st[S_DA] = da; st[S_DB] = db; st[S_XM] = xm; st[S_PE] = pe;
    st[S_S0] = s0; st[S_S1] = s1; st[S_S2] = s2; st[S_S3] = s3; st[S_PV] = pv;
    st[S_DEV] = dev; st[S_DG] = dg;
    return samples;
}

/* True if the firmware's 1 ms task at the end of cycle number `count` would change nothing:
 * Firmware.tick's every step, with the parameters fasttick.py derived from the firmware. */
static int tick_is_noop(const double *st, const double *c, const double *in, double *t,
                        int64_t count, int64_t tick)
{
    const double now = (double)count * t[T_CYCLE_S];
    if (t[T_BOOTING] != 0.0 && now >= t[T_BOOT_S] - 1e-9) return 0;
    const double ia = st[S_IA], ib = st[S_IB];
    double temperature = t[T_TEMPERATURE], rise = t[T_RISE];
    int temp_alarm = t[T_TEMP_ALARM] != 0.0;
    int64_t static_bits = (int64_t)t[T_STATIC_BITS];
    if (tick % (int64_t)t[T_THERMAL_TICKS] == 0) {
        /* thermal.step: the same expressions; anything beyond a new reading is left to Python */
        if (t[T_THERMAL] == 0.0) return 0;
        const double power = t[T_R_COIL] * (ia * ia + ib * ib) * 1e-6 + t[T_LOSS_W];
        rise += (t[T_K_PER_W] * power - rise) * t[T_DT] / t[T_TAU_S];
        temperature = t[T_AMBIENT] + rise;
        if (fabs(temperature - t[T_COIL_T]) > t[T_COIL_REFRESH_K]) return 0;
        const int warning = temperature > t[T_WARN_C] ||
                            (t[T_WARNING] != 0.0 && temperature > t[T_WARN_OFF_C]);
        if (warning != (t[T_WARNING] != 0.0)) return 0;
        temp_alarm = temperature > t[T_WARN_C];
        static_bits &= ~(int64_t)B_TEMPERATURE;
        if (temperature > t[T_TEMP_LIMIT]) static_bits |= B_TEMPERATURE;
    }
    const double ctrl_dev = c[C_PROCESS_ON] != 0.0 ? st[S_DEV] : st[S_R] - st[S_XM];
    const int beyond = fabs(ctrl_dev) > t[T_MON_THR];
    const double limit = t[T_OVERCURRENT_MA];
    const int alarm = ia > limit || ib > limit || temp_alarm ||
                      (beyond && t[T_STATE_ACTIVE] != 0.0);
    if (t[T_EVAL] != 0.0 || alarm) {
        /* FaultMonitor.update changes nothing if every raw condition is as last fed ... */
        int64_t mask = static_bits;
        const double supply = t[T_SUPPLY];
        if (t[T_HAS_A] != 0.0 &&
            (st[S_DA] * supply >= t[T_OPEN_MIN_V] ? ia < t[T_OPEN_MA] : t[T_COIL_OPEN_A] != 0.0))
            mask |= B_COIL_A_OPEN;
        if (t[T_HAS_B] != 0.0 &&
            (st[S_DB] * supply >= t[T_OPEN_MIN_V] ? ib < t[T_OPEN_MA] : t[T_COIL_OPEN_B] != 0.0))
            mask |= B_COIL_B_OPEN;
        double lvdt_ma = 0.0; /* as ckernel.CompiledLoop writes it back */
        if (in[I_LVDT_BREAK] == 0.0) {
            lvdt_ma = 12.0 + st[S_X] * c[C_LVDT_MA_K];
            if (!(lvdt_ma > c[C_LVDT_SAT])) lvdt_ma = c[C_LVDT_SAT];
        }
        if (lvdt_ma < t[T_LOOP_BREAK_MA]) mask |= B_POSITION;
        if (t[T_HAS_A] != 0.0 && (ia > limit || t[T_OC_HOLD_A] != 0.0)) mask |= B_COIL_A_OC;
        if (t[T_HAS_B] != 0.0 && (ib > limit || t[T_OC_HOLD_B] != 0.0)) mask |= B_COIL_B_OC;
        if (beyond && (t[T_STATE_ACTIVE] != 0.0 || t[T_PRESENT_MON] != 0.0)) mask |= B_MONITORING;
        if (mask != (int64_t)t[T_REF_MASK]) return 0;
        /* ... and no detection delay or display hold ends now */
        const int nd = (int)t[T_N_DEADLINES];
        for (int i = 0; i < nd; i++) {
            const double *d = t + T_DEADLINES + 3 * i;
            if (d[0] == 0.0 ? now - d[1] >= d[2] - 1e-9 : (0.0 <= d[1] && d[1] <= now))
                return 0;
        }
    }
    if (t[T_OVR_ON] != 0.0 && now - t[T_OVR_LAST] > t[T_OVR_TIMEOUT]) return 0;
    /* a no-op but for the thermal model: commit it (the caller hands the reading on) */
    t[T_RISE] = rise;
    t[T_TEMPERATURE] = temperature;
    t[T_TEMP_ALARM] = temp_alarm;
    t[T_STATIC_BITS] = (double)static_bits;
    return 1;
}

static int get(PyObject *obj, Py_buffer *view, Py_ssize_t count, const char *what)
{
    if (PyObject_GetBuffer(obj, view, PyBUF_WRITABLE | PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return -1;
    if (view->itemsize != sizeof(double) || view->format == NULL || strcmp(view->format, "d") ||
        view->len < count * (Py_ssize_t)sizeof(double)) {
        PyErr_Format(PyExc_ValueError, "%s: an array('d') of at least %zd items is needed", what,
                     count);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

PyDoc_STRVAR(run_doc,
"run(state, coefficients, inputs, n, countdown, tick, capture, program=None)\n"
"-> (cycles, ticks, samples, countdown)\n\n"
"Run up to n control cycles. Without tick parameters (None) exactly min(n, countdown) cycles.\n"
"With them, every 1 ms task due before n cycles that would change nothing is passed (counted\n"
"in ticks) until one would, which is left for the caller (countdown 0). Captured samples go\n"
"to capture (3 doubles each, room for n). program: the static setpoint chain (4 doubles:\n"
"raw, threshold, gain, linearized) of each of the n cycles, or None (the inputs' values).\n"
"The GIL is released while the cycles run (batches of 100 cycles or more).");

static PyObject *run(PyObject *self, PyObject *args)
{
    PyObject *o_st, *o_c, *o_in, *o_t, *o_cap, *o_prog = Py_None;
    long n, countdown;
    (void)self;
    if (!PyArg_ParseTuple(args, "OOOllOO|O", &o_st, &o_c, &o_in, &n, &countdown, &o_t, &o_cap,
                          &o_prog))
        return NULL;
    if (n < 0 || countdown < 1 || countdown > TICK_CYCLES) {
        PyErr_SetString(PyExc_ValueError, "run: n must be >= 0 and countdown 1...5");
        return NULL;
    }
    Py_buffer b_st, b_c, b_in, b_t = {0}, b_cap;
    if (get(o_st, &b_st, S_COUNT, "state") < 0) return NULL;
    if (get(o_c, &b_c, C_COUNT, "coefficients") < 0) goto fail_st;
    if (get(o_in, &b_in, I_COUNT, "inputs") < 0) goto fail_c;
    const int ticking = o_t != Py_None;
    if (ticking && get(o_t, &b_t, T_COUNT, "tick") < 0) goto fail_in;
    if (get(o_cap, &b_cap, 3 * n, "capture") < 0) goto fail_t;
    Py_buffer b_prog = {0};
    const int programmed = o_prog != Py_None;
    if (programmed && get(o_prog, &b_prog, 4 * n, "program") < 0) goto fail_cap;
    double *st = b_st.buf, *cap = b_cap.buf, *in = b_in.buf, *t = b_t.buf;
    const double *c = b_c.buf, *prog = b_prog.buf;
    long done = 0, ticks = 0;
    Py_ssize_t samples = 0;
    PyThreadState *released = n >= RELEASE_GIL_CYCLES ? PyEval_SaveThread() : NULL;
    if (!ticking) {
        done = n < countdown ? n : countdown;
        samples = cycles(st, c, in, done, cap, prog);
        countdown -= done;
    } else {
        /* int64_t, not long: Windows' long has 32 bits, and (long)2^40 there was negative */
        const int64_t max_ticks = (int64_t)t[T_MAX_TICKS];
        const int64_t count0 = (int64_t)t[T_CYCLES0], ticks0 = (int64_t)t[T_TICKS0];
        while (done < n) {
            long seg = n - done < countdown ? n - done : countdown;
            samples += cycles(st, c, in, seg, cap + 3 * samples, prog ? prog + 4 * done : NULL);
            done += seg;
            countdown -= seg;
            if (countdown > 0) break;
            if (ticks >= max_ticks || !tick_is_noop(st, c, in, t, count0 + done, ticks0 + ticks + 1))
                break;
            ticks++;
            in[I_TEMP10] = t[T_TEMPERATURE] * 10.0; /* Firmware._update_outputs' new reading */
            countdown = TICK_CYCLES;
        }
    }
    if (released != NULL) PyEval_RestoreThread(released);
    if (programmed) PyBuffer_Release(&b_prog);
    PyBuffer_Release(&b_cap);
    if (ticking) PyBuffer_Release(&b_t);
    PyBuffer_Release(&b_in);
    PyBuffer_Release(&b_c);
    PyBuffer_Release(&b_st);
    return Py_BuildValue("(llnl)", done, ticks, samples, countdown);
fail_cap:
    PyBuffer_Release(&b_cap);
fail_t:
    if (ticking) PyBuffer_Release(&b_t);
fail_in:
    PyBuffer_Release(&b_in);
fail_c:
    PyBuffer_Release(&b_c);
fail_st:
    PyBuffer_Release(&b_st);
    return NULL;
}

static PyMethodDef methods[] = {
    {"run", run, METH_VARARGS, run_doc},
    {NULL, NULL, 0, NULL},
};

static int exec_module(PyObject *m)
{
#ifndef SOURCE_HASH
#define SOURCE_HASH ""
#endif
    use_crt_sin();
    if (PyModule_AddStringConstant(m, "SOURCE_HASH", SOURCE_HASH) < 0) return -1;
    if (PyModule_AddIntConstant(m, "STATE_COUNT", S_COUNT) < 0) return -1;
    if (PyModule_AddIntConstant(m, "COEFFICIENT_COUNT", C_COUNT) < 0) return -1;
    if (PyModule_AddIntConstant(m, "INPUT_COUNT", I_COUNT) < 0) return -1;
    if (PyModule_AddIntConstant(m, "TICK_COUNT", T_COUNT) < 0) return -1;
    if (PyModule_AddIntConstant(m, "TICK_RISE", T_RISE) < 0) return -1;
    if (PyModule_AddIntConstant(m, "TICK_TEMPERATURE", T_TEMPERATURE) < 0) return -1;
    if (PyModule_AddIntConstant(m, "TICK_DEADLINES", T_DEADLINES) < 0) return -1;
    if (PyModule_AddIntConstant(m, "CURVE_POINTS", 16) < 0) return -1;
    if (PyModule_AddIntConstant(m, "MAX_DEADLINES", 16) < 0) return -1;
    return 0;
}

static PyModuleDef_Slot slots[] = {
    {Py_mod_exec, exec_module},
    {0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_ckernel",
    "The emulated valve's control loop, compiled (see prm9tool/device/emulator/ckernel.py).",
    0, methods, slots, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__ckernel(void) { return PyModuleDef_Init(&module); }
