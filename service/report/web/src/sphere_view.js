// The sphere of directions in SVG: Lambert azimuthal equal-area projections of the two
// hemispheres (+z seen from above: +x right, +y up; -z seen from below with the part
// turned over about x: +x right, +y down). Every surface's map: 2-cells filled, arcs as
// thick lines, points as dots -- the low-dimensional ones are through holes and slots and
// must stay visible. d3-geo clips the spherical polygons and arcs at the hemisphere edge.
import { geoAzimuthalEqualArea, geoPath, geoGraticule } from "d3-geo";
import { isEmptyImage } from "./data.js";

const SVG = "http://www.w3.org/2000/svg";
const kScale = 100;                 // projection scale: the hemisphere edge is at kScale*sqrt(2)
const kPanel = 2 * kScale * Math.SQRT2 + 50;

function el(name, attrs = {}, parent = null) {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

function lonLat(v) {
  const x = v.x || 0, y = v.y || 0, z = v.z || 0;
  const n = Math.hypot(x, y, z) || 1;
  return [(Math.atan2(y, x) * 180) / Math.PI, (Math.asin(Math.max(-1, Math.min(1, z / n))) * 180) / Math.PI];
}

// Our loops keep the set on their left seen from outside; d3 wants the opposite winding.
function ring(loop) {
  const r = (loop.vertices || []).map(lonLat).reverse();
  if (r.length) r.push(r[0]);
  return r;
}

function geometryOf(image) {
  if (image.fullSphere) return { type: "Sphere" };
  const polygons = (image.polygons || []).map((p) => (p.loops || []).map(ring));
  return { type: "MultiPolygon", coordinates: polygons };
}

function arcsOf(image) {
  return { type: "MultiLineString", coordinates: (image.arcs || []).map((a) => (a.vertices || []).map(lonLat)) };
}

// One hemisphere: its projection, outline, graticule and axis labels. d3 clips a little
// beyond the hemisphere and the SVG clip path cuts exactly at its edge: d3 draws nothing for
// a polygon whose boundary is exactly the clipping circle (a hemisphere bounded by the
// equator, the GVM of every flat face on z = const).
function hemisphere(svg, pole, x0) {
  const cx = x0 + kPanel / 2, cy = kPanel / 2 + 12, radius = kScale * Math.SQRT2;
  const projection = geoAzimuthalEqualArea().rotate(pole > 0 ? [90, -90] : [90, 90]).clipAngle(91)
    .scale(kScale).translate([cx, cy]).precision(0.2);
  const name = pole > 0 ? "+z" : "-z";
  const g = el("g", { class: "hemisphere", "data-pole": name, "data-cx": cx, "data-cy": cy, "data-radius": radius }, svg);
  const clipId = `hemisphere-clip${pole > 0 ? "-up" : "-down"}`;
  el("circle", { cx, cy, r: radius }, el("clipPath", { id: clipId }, g));
  el("circle", { class: "sphere-disc", cx, cy, r: radius }, g);
  const path = geoPath(projection);
  const inside = el("g", { "clip-path": `url(#${clipId})` }, g);
  el("path", { class: "graticule", d: path(geoGraticule().step([30, 30])()) }, inside);
  el("text", { class: "pole-label", x: cx, y: 14, "text-anchor": "middle" }, g).textContent =
    pole > 0 ? "upper hemisphere (+z), seen from above" : "lower hemisphere (-z), seen from below";
  for (const [label, v] of [["+x", { x: 1 }], ["-x", { x: -1 }], ["+y", { y: 1 }], ["-y", { y: -1 }]]) {
    const [px, py] = projection(lonLat(v));
    const dx = px - cx, dy = py - cy, n = Math.hypot(dx, dy) || 1;
    el("text", { class: "axis-label", x: px + (dx / n) * 12, y: py + (dy / n) * 12 + 4, "text-anchor": "middle" }, g)
      .textContent = label;
  }
  const maps = el("g", { class: "maps" }, inside);
  const dots = el("g", { class: "dots" }, g);    // whole dots, also on the equator
  const marks = el("g", { class: "marks" }, g);
  return { pole, projection, path, maps, dots, marks };
}

function visibleIn(hemi, v) {
  return hemi.pole > 0 ? (v.z || 0) >= 0 : (v.z || 0) <= 0;
}

export class SphereView {
  // surfaces: the surfaces drawn; colorOf(surface) its colour; setups: [{direction, color,
  // label, rotary}]; onSelect(surfaceId) when a map is clicked.
  constructor(container, surfaces, colorOf, setups, onSelect) {
    this.svg = el("svg", { class: "sphere", viewBox: `0 0 ${2 * kPanel} ${kPanel + 20}` });
    container.appendChild(this.svg);
    this.hemis = [hemisphere(this.svg, 1, 0), hemisphere(this.svg, -1, kPanel)];
    this.groups = new Map();
    const ordered = [...surfaces].sort((a, b) => (b.gvm?.area || 0) - (a.gvm?.area || 0));
    for (const s of ordered) this.drawSurface(s, colorOf(s), onSelect);
    setups.forEach((setup, i) => this.drawSetup(setup, i));
  }

  // One group per hemisphere for a surface whose map is not empty, all with the same
  // data-surface (the biggest maps first, so small ones stay on top).
  drawSurface(surface, color, onSelect) {
    const image = surface.gvm;   // unset when not computed (--lvm-only): nothing to draw
    if (isEmptyImage(image)) return;
    const id = surface.id || 0;
    const list = [];
    const group = (parent) => {
      const g = el("g", { class: surface.onHull ? "gvm hull" : "gvm", "data-surface": id }, parent);
      el("title", {}, g).textContent = `${surface.name || "S" + id}: ${image.description || ""}`;
      g.style.setProperty("--c", color);
      g.addEventListener("click", (e) => { e.stopPropagation(); onSelect(id); });
      list.push(g);
      return g;
    };
    for (const h of this.hemis) {
      const area = h.path(geometryOf(image));
      const arcs = h.path(arcsOf(image));
      const points = (image.points || []).filter((p) => visibleIn(h, p));
      if (!area && !arcs && !points.length) continue;
      const g = group(h.maps);
      if (area) el("path", { class: "cell2", d: area }, g);
      if (arcs) el("path", { class: "cell1", d: arcs }, g);
      if (!points.length) continue;
      const d = group(h.dots);
      for (const p of points) {
        const [x, y] = h.projection(lonLat(p));
        el("circle", { class: "cell0", cx: x, cy: y, r: 3.5 }, d);
      }
    }
    this.groups.set(id, list);
  }

  drawSetup(setup, index) {
    for (const h of this.hemis) {
      const g = el("g", { class: "setup-mark", "data-setup": index }, h.marks);
      g.style.setProperty("--c", setup.color);
      if (setup.rotary) {
        // The tool directions of a rotary axis: the great circle normal to it.
        const ring = [];
        for (let k = 0; k <= 72; ++k) ring.push(lonLat(circlePoint(setup.direction, (k * Math.PI) / 36)));
        const d = h.path({ type: "LineString", coordinates: ring });
        if (d) el("path", { class: "tool-circle", d }, g);
      }
      for (const v of setup.rotary ? [setup.direction, negate(setup.direction)] : [setup.direction]) {
        if (!visibleIn(h, v)) continue;
        const [x, y] = h.projection(lonLat(v));
        el("circle", { class: "mark", cx: x, cy: y, r: 8 }, g);
        el("text", { class: "mark-label", x, y: y + 4, "text-anchor": "middle" }, g).textContent = setup.label;
      }
    }
  }

  // Selected surfaces (a Set of ids, or null for none) stand out; the rest fade.
  highlight(selected) {
    this.svg.classList.toggle("has-selection", !!selected);
    for (const [id, groups] of this.groups) {
      for (const g of groups) g.classList.toggle("selected", !!selected && selected.has(id));
    }
  }

  highlightSetup(index) {
    for (const g of this.svg.querySelectorAll(".setup-mark")) {
      g.classList.toggle("selected", Number(g.dataset.setup) === index);
    }
  }
}

function negate(v) {
  return { x: -(v.x || 0), y: -(v.y || 0), z: -(v.z || 0) };
}

// A point of the great circle normal to axis a, at angle t.
function circlePoint(a, t) {
  const ax = [a.x || 0, a.y || 0, a.z || 0];
  const n = Math.hypot(...ax) || 1;
  const u = ax.map((c) => c / n);
  const helper = Math.abs(u[2]) < 0.9 ? [0, 0, 1] : [1, 0, 0];
  const e1 = normalize(cross(u, helper)), e2 = cross(u, e1);
  const p = e1.map((c, i) => Math.cos(t) * c + Math.sin(t) * e2[i]);
  return { x: p[0], y: p[1], z: p[2] };
}

function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

function normalize(v) {
  const n = Math.hypot(...v) || 1;
  return v.map((c) => c / n);
}
