// The report's tables, built from the protobuf JSON of the Analysis and the Plan.

export function h(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === "onclick") e.addEventListener("click", v);
    else if (k === "style") e.style.cssText = v;
    else e.setAttribute(k, v);
  }
  for (const c of children.flat()) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  return e;
}

export function table(headers, rows, attrs = {}) {
  return h("table", attrs, h("thead", {}, h("tr", {}, headers.map((x) => h("th", {}, x)))),
    h("tbody", {}, rows));
}

export function num(x, digits = 2) {
  return (x || 0).toFixed(digits).replace(/\.?0+$/, "") || "0";
}

export function direction(v) {
  return v ? `(${num(v.x, 4)}, ${num(v.y, 4)}, ${num(v.z, 4)})` : "";
}

export function swatch(color) {
  return h("span", { class: "swatch", style: `background:${color}` });
}

const kReasons = {
  UNREACHABLE_REASON_SELF_OCCLUDED: "undercut by its own shape (LVM(S) empty)",
  UNREACHABLE_REASON_NEIGHBOR_OCCLUDED: "blocked by the faces beside it (LVM(S + N_S) empty)",
  UNREACHABLE_REASON_OCCLUDED: "occluded by the rest of the part",
  UNREACHABLE_REASON_VOID: "faces an internal void",
  UNREACHABLE_REASON_NOT_ALONG_NORMAL: "not reachable along its own normal",
  UNREACHABLE_REASON_NO_HEAD_ORIENTATION: "no probe head orientation fits",
  UNREACHABLE_REASON_GVM_NOT_COMPUTED: "GVM not computed (--lvm-only)",
  UNREACHABLE_REASON_NO_CLEARANCE: "no direction with the required clearance",
};

export function reasonText(reason) {
  return kReasons[reason] || String(reason || "").toLowerCase();
}

function names(ids, nameOf, limit = 12) {
  const list = ids.map(nameOf);
  return list.length > limit ? `${list.slice(0, limit).join(", ")} … and ${list.length - limit} more` : list.join(", ");
}

// A setup's surfaces: pieces as "F7 (piece 2)", "~" after those reached only within the
// tolerance.
function reachNames(s, nameOf) {
  return (s.reach || []).map((r) => `${nameOf(r.feature || 0)}${r.piece ? ` (piece ${r.piece})` : ""}${r.withinTolerance ? "~" : ""}`);
}

// The setups, each row selecting its setup when clicked.
export function setupTable(plan, colorOfSetup, nameOf, onSelect) {
  const probe = plan.mode === "PLAN_MODE_PROBE", rotary = plan.mode === "PLAN_MODE_ROTARY";
  const headers = ["#", "", rotary ? "rotary axis" : "direction u (tool along −u)"];
  if (probe) headers.push("head A°", "head B°");
  if (rotary) headers.push("tool direction at 0°");
  headers.push("clearance°", "surfaces");
  const rows = (plan.setups || []).map((s, i) => {
    const surfaces = reachNames(s, nameOf);
    const cells = [i + 1, swatch(colorOfSetup(i)), direction(s.direction)];
    if (probe) cells.push(num(s.headADegrees), num(s.headBDegrees));
    if (rotary) cells.push(direction(s.rotaryZero));
    cells.push(s.exactAlignment ? "0 (exact alignment)" : num(s.clearanceDegrees, 1),
      `${surfaces.length}: ${names(surfaces, (x) => x)}`);
    return h("tr", { class: "setup-row", "data-setup": i, onclick: () => onSelect(i) }, cells.map((c) => h("td", {}, c)));
  });
  return table(headers, rows, { class: "setups" });
}

// What the tolerance did: the surfaces reached only within it, and by how much.
export function toleranceTable(plan, nameOf) {
  const t = plan.tolerance || {};
  const rows = [];
  (plan.setups || []).forEach((s, i) => {
    for (const r of s.reach || []) {
      if (!r.withinTolerance) continue;
      rows.push(h("tr", {}, h("td", {}, nameOf(r.feature || 0) + (r.piece ? ` (piece ${r.piece})` : "")),
        h("td", {}, i + 1), h("td", {}, Number(r.distanceRadians || 0).toExponential(1))));
    }
  });
  const n = (plan.setups || []).length, exact = t.exactSetups || 0;
  const summary = h("p", {}, `Tolerance ${Number(t.radians || 0).toExponential(1)} rad: ${n} setups within it` +
    (exact !== n ? `; ${exact} exactly (lower bound ${t.exactLowerBound || 0})` : ", as many as exactly") +
    `; ${rows.length} surfaces reached only within it.`);
  return rows.length ? [summary, table(["surface", "setup", "off its GVM by (rad)"], rows, { class: "within" })] : [summary];
}

// Surfaces planned piece by piece (no one direction sees all of them), and their setups.
export function piecesTable(plan, nameOf) {
  const unreachable = new Set((plan.unreachable || []).map((u) => u.feature || 0));
  const rows = (plan.surfaces || []).filter((s) => s.pieces).map((s) => h("tr", {},
    h("td", {}, nameOf(s.id || 0)), h("td", {}, s.pieces.count || 0),
    h("td", {}, (s.pieces.setups || []).map((k) => (k || 0) + 1).join(", ")),
    h("td", {}, unreachable.has(s.id || 0) ? "some pieces unreachable" : "every piece reached")));
  return table(["surface", "pieces", "setups", ""], rows, { class: "pieces" });
}

export function unreachableTable(plan, nameOf) {
  const rows = (plan.unreachable || []).map((u) => h("tr", {},
    h("td", {}, nameOf(u.feature || 0)), h("td", {}, reasonText(u.reason)), h("td", {}, u.detail || ""),
    h("td", {}, names(u.blockingFeatures || [], nameOf))));
  return table(["surface", "reason", "detail", "blocked by"], rows, { class: "unreachable" });
}

export function proofTable(plan, nameOf) {
  const s = plan.solver || {};
  const n = (plan.setups || []).length;
  const rows = [
    ["setups", n],
    ["lower bound", `${plan.lowerBound || 0} — ${plan.optimal ? "optimal: no plan has fewer setups" : "not proven optimal"}`],
    ["lower-bound witness", `${(plan.lowerBoundWitness || []).length} surfaces no two of which share a direction: ${names(plan.lowerBoundWitness || [], nameOf)}`],
    ["solver", s.solver || ""],
    ["candidate set", `${s.candidateSet || ""} (${s.candidates || 0} candidates, ${s.maximalCandidates || 0} inclusion-maximal)`],
    ["bounds", `greedy ${s.greedySetups || 0}, packing ${s.packingBound || 0}, LP ${num(s.lpBound, 3)}, nodes ${s.nodes || 0}`],
  ];
  if (plan.tolerance) {
    const t = plan.tolerance;
    rows.push(["tolerance", `${Number(t.radians || 0).toExponential(1)} rad; exactly: ${t.exactSetups || 0} setups, lower bound ${t.exactLowerBound || 0}`]);
  }
  if (s.continuousLowerBound) rows.push(["continuous lower bound", s.continuousLowerBound]);
  if (s.timeLimitReached) rows.push(["time limit", "reached: the best cover found is shown with its gap"]);
  return keyValue(rows, "proof");
}

export function keyValue(rows, cls) {
  return h("table", { class: `kv ${cls}` }, h("tbody", {}, rows.map(([k, v]) => h("tr", {}, h("th", {}, k), h("td", {}, v)))));
}

export function partTable(part) {
  const b = part.boundingBox || {};
  return keyValue([
    ["source", part.source || ""],
    ["faces / vertices / triangles", `${part.inputFaces || 0} / ${part.inputVertices || 0} / ${part.triangles || 0}`],
    ["shells (voids)", `${part.shells || 0} (${part.voidShells || 0})`],
    ["hull faces", part.hullFaces || 0],
    ["bounding box", `${direction(b.min)} – ${direction(b.max)}`],
    ["validation", part.validation || ""],
    ...(part.cadFaces ? [["STEP", `${part.cadFaces} B-rep faces, file unit ${part.fileUnit} (coordinates in mm), ` +
      `tessellated at ${num(part.linearDeflection, 4)} mm and ${num(part.angularDeflectionDegrees, 1)}°`],
      ["tessellation", tessellationText(part.stepTessellation || {})]] : []),
  ], "part");
}

// What the tessellation kept of the B-rep (the text report's line, gvm.v1.StepTessellation).
export function tessellationText(t) {
  if (!t.faithful) return "BRepMesh's triangles as they are (--brepmesh-only)";
  const exp = (x) => Number(x || 0).toExponential(1);
  const within = t.maxDirectionAngleRadians ? `within ${exp(t.maxDirectionAngleRadians)} rad of the B-rep's` : "as the B-rep gives them";
  let s = `faithful: ${(t.directions || []).length} B-rep directions kept exactly (${within}), ` +
    `${t.ruledFaces || 0} ruled faces meshed along their rulings, points moved at most ` +
    `${exp(t.maxNodeDisplacementMm)} mm`;
  const inexact = t.inexact || [];
  if (inexact.length) {
    const worst = Math.max(...inexact.map((r) => r.distanceMm || 0));
    s += `; ${inexact.length} relations kept within ${exp(worst)} mm only (where faces of two frames meet)`;
  }
  const left = t.brepmeshFaces || [];
  if (left.length) s += `; ${left.length} faces as BRepMesh made them (face ${left[0].cadFace || 0}: ${left[0].reason})`;
  return s;
}

export function timingTable(analysis, plan) {
  const t = analysis.timing || {};
  const rows = [["analysis", `${num(t.totalSeconds, 3)} s (read ${num(t.readSeconds, 3)}, validate ${num(t.validateSeconds, 3)}, part ${num(t.partSeconds, 3)}, maps ${num(t.visibilitySeconds, 3)}) on ${t.threads || 0} threads`]];
  if (plan && plan.timing) {
    const p = plan.timing;
    rows.push(["planning", `${num(p.totalSeconds, 3)} s (candidates ${num(p.candidatesSeconds, 3)}, cover ${num(p.coverSeconds, 3)}, placement ${num(p.placementSeconds, 3)}, unreachable ${num(p.unreachableSeconds, 3)})`]);
  }
  rows.push(["engine", analysis.engineVersion || ""]);
  return keyValue(rows, "timing");
}

// Every surface with its map, for the analysis report (and as details of a plan).
export function surfaceTable(surfaces, regions, colorOf, setupOf, onSelect) {
  const rows = surfaces.map((s) => {
    const info = s.info || {};
    const image = s.gvm || s.lvm || {};
    const setup = setupOf ? setupOf(s) : "";
    return h("tr", { class: "surface-row", "data-surface": s.id || 0, onclick: () => onSelect(s.id || 0) },
      h("td", {}, s.id || 0), h("td", {}, swatch(colorOf(s)), " ", s.name || ""), h("td", {}, (s.faces || []).length),
      h("td", {}, regions ? "concave region" : s.onHull ? "hull" : `region ${s.region || 0}`),
      h("td", {}, (s.gvm ? "" : "LVM only: ") + (image.description || "")),
      h("td", {}, num(image.area, 4)), h("td", {}, info.neighborOccluders || 0), h("td", {}, info.potentialOccluders || 0),
      h("td", {}, num(info.seconds, 3)), setupOf ? h("td", {}, setup) : "");
  });
  const headers = ["id", "name", "faces", "where", "GVM", "area sr", "|N_S|", "|O_S|", "s"];
  if (setupOf) headers.push("setup");
  return table(headers, rows, { class: "surfaces" });
}
