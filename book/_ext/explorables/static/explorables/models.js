/* Physics for the explorables: a small port of physics_figures.models (closed forms,
 * and the same fixed-step RK4 for the few seconds a parachute takes to open).
 *
 * Every function here has a Python twin (physics_figures.models or
 * physics_figures.explorables) and tests/test_explorables_models.py runs this file
 * under node and checks it against the twin on many random inputs (to 1e-9 relative,
 * 1e-6 for the integrated skydive).
 * SI units throughout; velocities are signed along a chosen positive direction.
 * Works as a browser global (window.ExplorableModels) and as a node module.
 */
(function (root) {
  "use strict";

  var DEG = Math.PI / 180;

  /* ---- drag (quadratic: D = k v^2, k in kg m^-1); twin: physics_figures.models.drag ---- */

  var WITHIN_TERMINAL = 0.01; // "terminal velocity reached" = within 1 % of it (C and E)

  function dragForce(k, speed) {
    return k * speed * speed;
  }

  /** v_t = sqrt(m g / k): the speed at which the drag equals the weight. */
  function terminalVelocity(mass, k, g) {
    return Math.sqrt((mass * g) / k);
  }

  /** v = v_t tanh(g t / v_t): falling from rest, down positive. */
  function velocityFromRest(t, vt, g) {
    return vt * Math.tanh((g * t) / vt);
  }

  /** v = v_t coth(g t / v_t + arcoth(v0 / v_t)) for v0 > v_t: slowing down to v_t. */
  function velocitySlowingToTerminal(t, v0, vt, g) {
    return vt / Math.tanh((g * t) / vt + Math.atanh(vt / v0)); // arcoth(x) = artanh(1/x)
  }

  /** Time from rest to within 1 % of v_t: t_C = (v_t / g) artanh(0.99). */
  function timeToTerminalVelocity(vt, g) {
    return (vt / g) * Math.atanh(1 - WITHIN_TERMINAL);
  }

  /** Time to slow from v0 > v_t to within 1 % of v_t (0 if already there). */
  function timeToSlowToTerminal(v0, vt, g) {
    return Math.max(0, (vt / g) * (Math.atanh(1 / (1 + WITHIN_TERMINAL)) - Math.atanh(vt / v0)));
  }

  /**
   * Earliest opening that still slows the skydiver to the parachute's terminal velocity:
   * the speed from rest must first pass 1.01 v_t2 (twin: models.earliest_opening).
   */
  function earliestOpening(vt1, vt2, g) {
    return (vt1 / g) * Math.atanh((vt2 * (1 + WITHIN_TERMINAL)) / vt1);
  }

  /** The same from the explorer's sliders (twin: explorables.earliest_parachute_opening). */
  function earliestParachuteOpening(mass, bodyDrag, parachuteDrag, g) {
    return earliestOpening(terminalVelocity(mass, bodyDrag, g), terminalVelocity(mass, parachuteDrag, g), g);
  }

  /** k(s) = k1 + (k2 - k1) min(1, s / tau)^2: the canopy fills over tau (twin: canopy_drag_constant). */
  function canopyDragConstant(s, k1, k2, tau) {
    var f = Math.min(1, Math.max(0, s / tau));
    return k1 + (k2 - k1) * f * f;
  }

  var OPENING_STEPS = 2000; // as physics_figures.models.drag.OPENING_STEPS

  /**
   * m dv/ds = m g - k(s) v^2 over the opening, s from 0 to tau, by classic fixed-step RK4
   * (twin: models.open_canopy, the same steps in the same order, so the two agree to rounding).
   */
  function openCanopy(m, v0, k1, k2, tau, g, steps) {
    var h = tau / steps;
    function rate(s, v) {
      var f = Math.min(1, s / tau);
      var k = k1 + (k2 - k1) * f * f;
      return g - (k * v * v) / m;
    }
    var v = v0,
      x = 0;
    var velocity = [v],
      distance = [x],
      time = [0],
      acceleration = [];
    for (var i = 0; i < steps; i++) {
      var s = i * h;
      var a1 = rate(s, v);
      var v2 = v + (h / 2) * a1;
      var a2 = rate(s + h / 2, v2);
      var v3 = v + (h / 2) * a2;
      var a3 = rate(s + h / 2, v3);
      var v4 = v + h * a3;
      var a4 = rate(s + h, v4);
      x = x + (h / 6) * (v + 2 * v2 + 2 * v3 + v4);
      v = v + (h / 6) * (a1 + 2 * a2 + 2 * a3 + a4);
      velocity.push(v);
      distance.push(x);
      time.push((i + 1) * h);
    }
    for (var j = 0; j <= steps; j++) {
      var sj = j * h;
      acceleration.push(g - (canopyDragConstant(sj, k1, k2, tau) * velocity[j] * velocity[j]) / m);
    }
    return { step: h, timeSinceOpening: time, velocity: velocity, distance: distance, acceleration: acceleration };
  }

  /* The velocity s seconds into the canopy's opening (0 <= s < its duration): Hermite
   * interpolation between openCanopy's steps, from v and dv/dt at both ends. */
  function velocityWhileOpening(opening, s) {
    var h = opening.step;
    var i = Math.min(OPENING_STEPS - 1, Math.max(0, Math.floor(Math.max(s, 0) / h)));
    var th = (s - i * h) / h,
      om = 1 - th;
    var v = opening.velocity,
      a = opening.acceleration;
    return (
      (1 + 2 * th) * om * om * v[i] +
      th * om * om * h * a[i] +
      th * th * (3 - 2 * th) * v[i + 1] +
      th * th * (th - 1) * h * a[i + 1]
    );
  }

  /* D: the step of the opening with the largest deceleration (the first, if two are equal). */
  function largestDecelerationStep(opening) {
    var peak = 0;
    for (var j = 1; j <= OPENING_STEPS; j++) if (opening.acceleration[j] < opening.acceleration[peak]) peak = j;
    return peak;
  }

  /* E: when the speed first comes within 1 % of v_t2 (vE), during the opening (linearly between
   * steps) or after it, on the coth curve from vFull. */
  function timeWithinParachuteTerminal(opening, tOpen, tau, vFull, vt2, g) {
    var vE = vt2 * (1 + WITHIN_TERMINAL);
    for (var e = 0; e <= OPENING_STEPS; e++) {
      if (opening.velocity[e] <= vE) {
        var va = opening.velocity[e - 1],
          vb = opening.velocity[e];
        return tOpen + opening.timeSinceOpening[e - 1] + ((va - vE) / (va - vb)) * opening.step;
      }
    }
    return tOpen + tau + timeToSlowToTerminal(vFull, vt2, g);
  }

  /* Points A to E, [time, velocity] each: A the start, B half of v_t1 and C within 1 % of it
   * (only if reached before the opening), D the largest deceleration, E within 1 % of v_t2. */
  function skydivePoints(opening, tOpen, tau, vt1, vt2, g) {
    var peak = largestDecelerationStep(opening);
    var vFull = opening.velocity[OPENING_STEPS];
    var vE = vt2 * (1 + WITHIN_TERMINAL);
    var tE = timeWithinParachuteTerminal(opening, tOpen, tau, vFull, vt2, g);
    var vC = vt1 * (1 - WITHIN_TERMINAL);
    var tB = (vt1 / g) * Math.atanh(0.5),
      tC = timeToTerminalVelocity(vt1, g);
    var points = { A: [0, 0] };
    if (tB < tOpen) points.B = [tB, vt1 / 2];
    if (tC <= tOpen) points.C = [tC, vC];
    points.D = [tOpen + opening.timeSinceOpening[peak], opening.velocity[peak]];
    points.E = [tE, vE];
    return points;
  }

  /**
   * A skydive with quadratic drag (twin: physics_figures.models.skydive): free fall from
   * rest with drag constant bodyDrag; from parachuteOpensAt the canopy fills over
   * openingDuration and the drag constant grows to parachuteDrag. Down positive.
   * Points A to E as the model puts them (B and C only if reached before the opening);
   * D is where the deceleration is largest.
   */
  function skydive(opts) {
    var g = opts.g;
    var m = opts.mass;
    var tOpen = opts.parachuteOpensAt;
    var tau = opts.openingDuration;
    var weight = m * g;
    var vt1 = terminalVelocity(m, opts.bodyDrag, g);
    var vt2 = terminalVelocity(m, opts.parachuteDrag, g);
    // the model's drag constants are k = m g / v_t^2, as in physics_figures
    var k1 = weight / (vt1 * vt1);
    var k2 = weight / (vt2 * vt2);
    var vOpen = vt1 * Math.tanh((g * tOpen) / vt1);
    var opening = openCanopy(m, vOpen, k1, k2, tau, g, OPENING_STEPS);
    var vFull = opening.velocity[OPENING_STEPS];
    var c = Math.atanh(vt2 / vFull); // arcoth(vFull / vt2)

    function dragConstantAt(t) {
      return canopyDragConstant(t - tOpen, k1, k2, tau);
    }
    function velocityAt(t) {
      var s = t - tOpen;
      if (s < 0) return vt1 * Math.tanh((g * t) / vt1);
      if (s >= tau) return vt2 / Math.tanh((g * (s - tau)) / vt2 + c);
      return velocityWhileOpening(opening, s);
    }
    function dragAt(t) {
      var v = velocityAt(t);
      return dragConstantAt(t) * v * v;
    }
    function resultantForceAt(t) {
      return weight - dragAt(t);
    }
    function accelerationAt(t) {
      return resultantForceAt(t) / m;
    }

    var points = skydivePoints(opening, tOpen, tau, vt1, vt2, g);
    var pointDrag = {},
      pointAcceleration = {};
    Object.keys(points).forEach(function (label) {
      var pt = points[label];
      pointDrag[label] = canopyDragConstant(pt[0] - tOpen, k1, k2, tau) * pt[1] * pt[1];
      pointAcceleration[label] = (weight - pointDrag[label]) / m;
    });
    return {
      mass: m,
      g: g,
      weight: weight,
      parachuteOpensAt: tOpen,
      openingDuration: tau,
      parachuteOpenAt: tOpen + tau,
      // the speed the canopy starts to open at (faster than at D, where the deceleration peaks)
      speedAtOpening: vOpen,
      terminalVelocityFreefall: vt1,
      terminalVelocityParachute: vt2,
      dragConstantFreefall: k1,
      dragConstantParachute: k2,
      // at each terminal velocity the drag is k v_t^2 (= the weight)
      dragAtFreefallTerminal: dragForce(k1, vt1),
      dragAtParachuteTerminal: dragForce(k2, vt2),
      points: points,
      pointDrag: pointDrag,
      pointAcceleration: pointAcceleration,
      velocityAt: velocityAt,
      dragConstantAt: dragConstantAt,
      dragAt: dragAt,
      resultantForceAt: resultantForceAt,
      accelerationAt: accelerationAt,
    };
  }

  /**
   * The numbers the explorer's "Unrealistic" warning quotes (twin:
   * physics_figures.explorables.opening_jolt): the largest deceleration in g (at D), the
   * speed the parachute starts to open at and the time it takes to fill. The keys are the
   * placeholders of physics_figures.explorables.UNREALISTIC_OPENING.
   */
  function openingJolt(dive) {
    return {
      in_g: -dive.pointAcceleration.D / dive.g,
      speed_at_opening: dive.speedAtOpening,
      opening_duration: dive.openingDuration,
    };
  }

  /* ---- collisions in a line (velocities signed) ---- */

  function totalMomentum(masses, velocities) {
    var p = 0;
    for (var i = 0; i < masses.length; i++) p += masses[i] * velocities[i];
    return p;
  }

  function totalKineticEnergy(masses, velocities) {
    var e = 0;
    for (var i = 0; i < masses.length; i++) e += 0.5 * masses[i] * velocities[i] * velocities[i];
    return e;
  }

  function relativeSpeed(va, vb) {
    return Math.abs(va - vb);
  }

  /** Elastic: momentum and kinetic energy conserved, approach speed = separation speed. */
  function elasticCollision(m1, u1, m2, u2) {
    var M = m1 + m2;
    return [((m1 - m2) * u1 + 2 * m2 * u2) / M, ((m2 - m1) * u2 + 2 * m1 * u1) / M];
  }

  /** Stick together: v = (m1 u1 + m2 u2) / (m1 + m2). */
  function stickTogether(m1, u1, m2, u2) {
    return (m1 * u1 + m2 * u2) / (m1 + m2);
  }

  /** Explosion from rest: 0 = m1 v1 + m2 v2, so v2 = -m1 v1 / m2. */
  function explosionFromRest(m1, m2, v1) {
    return (-m1 * v1) / m2;
  }

  /**
   * Keep a fraction f of the kinetic energy seen from the centre of mass (f = 1 elastic,
   * f = 0 stick together): each velocity relative to the centre of mass reverses and
   * shrinks by sqrt(f).
   */
  function collisionWithEnergyKept(m1, u1, m2, u2, f) {
    var vcm = (m1 * u1 + m2 * u2) / (m1 + m2);
    var s = Math.sqrt(f);
    return [vcm - s * (u1 - vcm), vcm - s * (u2 - vcm)];
  }

  function percentageKineticEnergyLost(before, after) {
    return ((before - after) / before) * 100;
  }

  /** Percentage of the kinetic energy lost; 0 when there was none to lose (all at rest). */
  function percentLost(before, after) {
    return before > 0 ? percentageKineticEnergyLost(before, after) : 0;
  }

  /** Percentage of the kinetic energy lost by sticking together: the most any collision loses.
   * Never below 0 (rounding, when A barely catches B: as the Python twin). */
  function mostPercentLost(m1, u1, m2, u2) {
    var v = stickTogether(m1, u1, m2, u2);
    var lost = percentLost(totalKineticEnergy([m1, m2], [u1, u2]), totalKineticEnergy([m1, m2], [v, v]));
    return Math.max(0, lost);
  }

  /**
   * The collision lab (twin: physics_figures.explorables.collision_lab). A (m1, u1) on the
   * left, B (m2, u2) on the right; kind "elastic", "stick", "loss" (percentLost of the
   * kinetic energy) or "explosion" (from rest; A moves off at velocityAAfter). An
   * impossible set-up comes back with after = null and refusal naming the broken rule.
   */
  function collisionLab(s) {
    var m1 = s.m1,
      m2 = s.m2;
    var explosion = s.kind === "explosion";
    var u1 = explosion ? 0 : s.u1;
    var u2 = explosion ? 0 : s.u2;
    var masses = [m1, m2];
    var result = {
      kind: s.kind,
      before: [u1, u2],
      after: null,
      refusal: null,
      numbers: {},
      momentumBefore: totalMomentum(masses, [u1, u2]),
      kineticEnergyBefore: totalKineticEnergy(masses, [u1, u2]),
      momentumAfter: null,
      kineticEnergyAfter: null,
      approachSpeed: relativeSpeed(u1, u2),
      separationSpeed: null,
      percentLost: null,
      mostPercentLost: explosion ? null : mostPercentLost(m1, u1, m2, u2),
    };
    function refused(code, numbers) {
      result.refusal = code;
      result.numbers = numbers || {};
      return result;
    }
    var after;
    if (explosion) {
      if (s.velocityAAfter > 0) return refused("explosion-wrong-way");
      after = [s.velocityAAfter, explosionFromRest(m1, m2, s.velocityAAfter)];
    } else {
      if (u1 <= u2) return refused("never-meet", { u1: u1, u2: u2 });
      if (s.kind === "elastic") after = elasticCollision(m1, u1, m2, u2);
      else if (s.kind === "stick") {
        var v = stickTogether(m1, u1, m2, u2);
        after = [v, v];
      } else {
        var most = result.mostPercentLost;
        if (s.percentLost < 0) return refused("energy-created");
        // a hair of tolerance so that typing the sticking-together figure is allowed
        if (s.percentLost > most * (1 + 1e-9))
          return refused("more-than-sticking", { momentum: result.momentumBefore, most: most });
        // the loss as a fraction of what can be lost (the centre-of-mass kinetic energy)
        var kept = most > 0 ? Math.max(0, 1 - s.percentLost / most) : 1;
        after = collisionWithEnergyKept(m1, u1, m2, u2, kept);
      }
    }
    result.after = after;
    result.momentumAfter = totalMomentum(masses, after);
    result.kineticEnergyAfter = totalKineticEnergy(masses, after);
    result.separationSpeed = relativeSpeed(after[0], after[1]);
    if (!explosion) result.percentLost = percentLost(result.kineticEnergyBefore, result.kineticEnergyAfter);
    return result;
  }

  /* ---- momentum in two dimensions (angles in degrees from the original line) ---- */

  function components(magnitude, angleDeg) {
    return [magnitude * Math.cos(angleDeg * DEG), magnitude * Math.sin(angleDeg * DEG)];
  }

  function fromComponents(along, across) {
    return [Math.hypot(along, across), Math.atan2(across, along) / DEG];
  }

  /**
   * The other body's momentum from conservation along and across the line: along =
   * p_before - p cos(theta); across = p sin(theta) (a size, on the other side of the line).
   */
  function missingMomentum(pBefore, pKnown, angleKnownDeg) {
    var known = components(pKnown, angleKnownDeg);
    var along = pBefore - known[0];
    var across = known[1];
    var polar = fromComponents(along, across);
    return { along: along, across: across, magnitude: polar[0], angleDeg: polar[1] };
  }

  /* ---- a piecewise-linear momentum-time graph ---- */

  function momentumHistory(times, momenta) {
    var n = times.length;
    function segmentIndex(t) {
      // the segment whose [t0, t1) holds t; the last segment also owns its end point
      for (var i = 0; i < n - 2; i++) if (t < times[i + 1]) return i;
      return n - 2;
    }
    function gradient(i) {
      return (momenta[i + 1] - momenta[i]) / (times[i + 1] - times[i]);
    }
    return {
      times: times,
      momenta: momenta,
      momentumAt: function (t) {
        var i = segmentIndex(t);
        return momenta[i] + gradient(i) * (t - times[i]);
      },
      forceAt: function (t) {
        return gradient(segmentIndex(t));
      },
      velocityAt: function (t, mass) {
        return this.momentumAt(t) / mass;
      },
    };
  }

  var api = {
    dragForce: dragForce,
    terminalVelocity: terminalVelocity,
    velocityFromRest: velocityFromRest,
    velocitySlowingToTerminal: velocitySlowingToTerminal,
    timeToTerminalVelocity: timeToTerminalVelocity,
    timeToSlowToTerminal: timeToSlowToTerminal,
    earliestOpening: earliestOpening,
    earliestParachuteOpening: earliestParachuteOpening,
    canopyDragConstant: canopyDragConstant,
    openCanopy: openCanopy,
    OPENING_STEPS: OPENING_STEPS,
    skydive: skydive,
    openingJolt: openingJolt,
    totalMomentum: totalMomentum,
    totalKineticEnergy: totalKineticEnergy,
    relativeSpeed: relativeSpeed,
    elasticCollision: elasticCollision,
    stickTogether: stickTogether,
    explosionFromRest: explosionFromRest,
    collisionWithEnergyKept: collisionWithEnergyKept,
    percentageKineticEnergyLost: percentageKineticEnergyLost,
    collisionLab: collisionLab,
    components: components,
    fromComponents: fromComponents,
    missingMomentum: missingMomentum,
    momentumHistory: momentumHistory,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.ExplorableModels = api;
})(typeof self !== "undefined" ? self : this);
