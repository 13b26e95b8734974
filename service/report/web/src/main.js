// The report page: the part in 3D coloured by setup, the sphere of directions, and the
// tables; selecting a setup (a row, a legend entry, a mark) or a surface (a face, a map,
// a row) highlights it everywhere.
import "./style.css";
import { readReportData, surfacesOf, setupOfSurface } from "./data.js";
import { PartView } from "./part_view.js";
import { SphereView } from "./sphere_view.js";
import * as T from "./tables.js";

const data = await readReportData();
const plan = data.plan || null;
const surfaces = surfacesOf(data);
const byId = new Map(surfaces.map((s) => [s.id || 0, s]));
const setupOf = setupOfSurface(data);
const classColor = (c) => data.classes[c].color;
const colorOfSurface = (s) => classColor(data.surfaceClass[s.id || 0]);
const setupClass = (i) => data.classes.findIndex((c) => c.setup === i);
const colorOfSetup = (i) => classColor(setupClass(i));
const nameOf = (id) => (byId.get(id) ? byId.get(id).name || `S${id}` : `S${id}`);
const $ = (id) => document.getElementById(id);

let part = null;
let sphere = null;

// The surfaces a setup reaches, whole or in pieces.
function surfacesOfSetup(i) {
  const s = plan.setups[i];
  return new Set([...(s.features || []), ...(s.reach || []).map((r) => r.feature || 0)]);
}

function selectSetup(i) {
  const sel = i === null ? null : surfacesOfSetup(i);
  part?.highlight(i === null ? null : new Set([setupClass(i)]));
  sphere.highlight(sel);
  sphere.highlightSetup(i);
  for (const row of document.querySelectorAll(".setup-row")) row.classList.toggle("selected", Number(row.dataset.setup) === i);
  const d = i === null ? null : plan.setups[i].direction || {};
  if (d) part?.viewAlong([d.x || 0, d.y || 0, d.z || 0]);
  showInfo(i === null ? "" : setupInfo(i));
}

function selectSurface(id) {
  part?.highlight(null, id);
  sphere.highlight(new Set([id]));
  sphere.highlightSetup(null);
  showInfo(surfaceInfo(id));
}

function setupInfo(i) {
  const s = plan.setups[i];
  return `Setup ${i + 1}: u = ${T.direction(s.direction)}, ${surfacesOfSetup(i).size} surfaces, clearance ${s.exactAlignment ? "0 (exact alignment)" : T.num(s.clearanceDegrees, 1) + "°"}`;
}

function surfaceInfo(id, face = null) {
  const s = byId.get(id);
  if (!s) return face === null ? "" : `face ${face}: hull face, not planned`;
  const setup = setupOf.get(id);
  const where = plan ? (setup === undefined ? "not planned" : typeof setup === "string" ? setup : setup >= 0 ? `setup ${setup + 1}` : "unreachable") : "";
  const image = s.gvm || s.lvm || {};
  const cad = s.cadFace ? ` · B-rep face ${s.cadFace.index || 0}, ${s.cadFace.surfaceType}` +
    (s.cadFace.axis ? ` about ${T.direction(s.cadFace.axis)}` : "") : "";
  return `${face === null ? "" : `face ${face} · `}${s.name || "S" + id} (${(s.faces || []).length} faces)${cad}${where ? " · " + where : ""} · GVM: ${image.description || "not computed"}`;
}

function showInfo(text) {
  $("info").textContent = text;
}

function onPick(face, clicked) {
  const id = face === null ? -1 : data.mesh.faceSurface[face];
  if (clicked) {
    if (face === null) selectSetup(null);
    else selectSurface(id);
  } else if (face !== null) {
    showInfo(surfaceInfo(id, face));
  }
}

function legend() {
  return data.classes.map((c, i) => T.h("span", { class: "legend-entry", "data-class": i,
    onclick: () => (c.setup !== undefined ? selectSetup(c.setup) : selectSetup(null)) }, T.swatch(c.color), " ", c.label));
}

function headline() {
  const a = data.analysis;
  if (!plan) {
    const n = (a.features || []).length;
    return `${n} features, ${(a.regions || []).length} concave regions`;
  }
  const n = (plan.setups || []).length;
  const kind = { PLAN_MODE_ROTARY: "rotary axes", PLAN_MODE_PROBE: "probe orientations" }[plan.mode] || "setups";
  return `${n} ${kind}, ${plan.optimal ? `optimal (lower bound ${plan.lowerBound || 0})` : `lower bound ${plan.lowerBound || 0}`}` +
    ` · ${plan.reached || 0} surfaces reached, ${plan.unreachableCount || 0} unreachable`;
}

function buildTables() {
  const out = $("tables");
  const section = (title, ...content) => out.append(T.h("section", {}, T.h("h2", {}, title), ...content));
  if (plan) {
    section("Setups", T.setupTable(plan, colorOfSetup, nameOf, selectSetup));
    if (plan.tolerance) section("Tolerance", ...T.toleranceTable(plan, nameOf));
    if ((plan.surfaces || []).some((s) => s.pieces)) section("Planned piece by piece", T.piecesTable(plan, nameOf));
    if ((plan.unreachable || []).length) section("Unreachable", T.unreachableTable(plan, nameOf));
    section("Proof of optimality", T.proofTable(plan, nameOf));
  }
  const regions = plan?.surfacesKind === "PLAN_SURFACES_REGIONS";
  const list = T.surfaceTable(surfaces, regions, colorOfSurface,
    plan ? (s) => { const k = setupOf.get(s.id || 0); return k === undefined ? "" : typeof k === "string" ? k : k >= 0 ? k + 1 : "unreachable"; } : null,
    selectSurface);
  section(regions ? "Concave regions" : "Features", plan ? T.h("details", {}, T.h("summary", {}, `${surfaces.length} surfaces`), list) : list);
  section("Part", T.partTable(data.analysis.part || {}));
  section("Timings", T.timingTable(data.analysis, plan));
}

function start() {
  document.title = data.title;
  $("title").textContent = data.title;
  $("headline").textContent = headline();
  $("legend").append(...legend());
  const setups = (plan?.setups || []).map((s, i) => ({ direction: s.direction || {}, color: colorOfSetup(i),
    label: String(i + 1), rotary: plan.mode === "PLAN_MODE_ROTARY" }));
  sphere = new SphereView($("sphere"), surfaces, colorOfSurface, setups, selectSurface);
  try {
    part = new PartView($("part"), data, onPick);
  } catch (e) {
    $("part").classList.add("no-webgl");
    $("part").textContent = "3D view unavailable (no WebGL in this browser): see the views along each setup below.";
  }
  buildTables();
  document.body.dataset.ready = "true";
}

start();
