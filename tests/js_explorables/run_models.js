// Runs the explorables' JavaScript models on cases read as JSON from stdin and prints
// the results as JSON, for tests/no_site/test_explorables_models.py to compare with Python.
//
// A case is {"call": name, "args": [...]} for a plain function, or one of the
// compound calls below that evaluate a model object at many points.
"use strict";
const path = require("path");
const models = require(
  path.join(__dirname, "..", "..", "book", "_ext", "explorables", "static", "explorables", "models.js"),
);

function run(c) {
  if (c.call === "skydive") {
    const dive = models.skydive(c.opts);
    const at = (f) => c.times.map((t) => f(t));
    return {
      weight: dive.weight,
      terminalVelocityFreefall: dive.terminalVelocityFreefall,
      terminalVelocityParachute: dive.terminalVelocityParachute,
      dragConstantFreefall: dive.dragConstantFreefall,
      dragConstantParachute: dive.dragConstantParachute,
      dragAtFreefallTerminal: dive.dragAtFreefallTerminal,
      dragAtParachuteTerminal: dive.dragAtParachuteTerminal,
      points: dive.points,
      pointDrag: dive.pointDrag,
      pointAcceleration: dive.pointAcceleration,
      speedAtOpening: dive.speedAtOpening,
      openingJolt: models.openingJolt(dive),
      velocity: at(dive.velocityAt),
      dragConstant: at(dive.dragConstantAt),
      drag: at(dive.dragAt),
      resultantForce: at(dive.resultantForceAt),
      acceleration: at(dive.accelerationAt),
    };
  }
  if (c.call === "openCanopy") {
    return models.openCanopy.apply(null, c.args);
  }
  if (c.call === "momentumHistory") {
    const history = models.momentumHistory(c.times, c.momenta);
    return {
      momentum: c.at.map((t) => history.momentumAt(t)),
      force: c.at.map((t) => history.forceAt(t)),
      velocity: c.at.map((t) => history.velocityAt(t, c.mass)),
    };
  }
  if (typeof models[c.call] !== "function") throw new Error("no model function " + c.call);
  return models[c.call].apply(null, c.args);
}

let input = "";
process.stdin.setEncoding("utf8");
process.stdin.on("data", (chunk) => (input += chunk));
process.stdin.on("end", () => {
  process.stdout.write(JSON.stringify(JSON.parse(input).map(run)));
});
