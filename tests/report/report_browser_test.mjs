// Opens a report written by `gvm plan --report` in headless Chromium (Debian's, driven by
// playwright-core) and checks what a person would see: no console errors, nothing fetched
// from outside the file, a 3D view that is not blank and shows every setup's colour, the
// sphere with one mark per setup (where the projection puts the direction) and one shape
// per non-empty GVM, and a static picture per setup.
//
//   node report_browser_test.mjs --gvm GVM --part PART --out DIR [gvm plan options...]
// Environment: GVM_NODE_MODULES (the build's node_modules), CHROMIUM (default /usr/bin/chromium).
import { execFileSync } from "node:child_process";
import { createRequire } from "node:module";
import fs from "node:fs";
import path from "node:path";

const args = process.argv.slice(2);
const option = (name) => { const i = args.indexOf(name); return i >= 0 ? args.splice(i, 2)[1] : null; };
const gvm = option("--gvm"), part = option("--part"), out = option("--out");
const chromiumPath = process.env.CHROMIUM || "/usr/bin/chromium";
if (!gvm || !part || !out) throw new Error("usage: --gvm GVM --part PART --out DIR [plan options]");
if (!fs.existsSync(chromiumPath)) {
  console.log(`SKIP: no Chromium at ${chromiumPath} (install Debian's chromium)`);
  process.exit(77);
}
const { chromium } = createRequire(path.join(process.env.GVM_NODE_MODULES, "x.js"))("playwright-core");

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
}

// The plan, its analysis and its report, written by the real command line.
fs.mkdirSync(out, { recursive: true });
const base = path.join(out, path.basename(part).replace(/\.[^.]*$/, ""));
const files = { html: `${base}-plan.html`, plan: `${base}-plan.json`, analysis: `${base}-analysis.json` };
execFileSync(gvm, ["plan", part, "--report", files.html, "--json", files.plan, "--analysis-json", files.analysis, "-q", ...args],
  { stdio: "inherit" });
const plan = JSON.parse(fs.readFileSync(files.plan, "utf8"));
const analysis = JSON.parse(fs.readFileSync(files.analysis, "utf8"));
const setups = plan.setups || [];
const surfaces = plan.surfacesKind === "PLAN_SURFACES_REGIONS" ? analysis.regions : analysis.features;
const nonEmpty = surfaces.filter((s) => s.gvm && (s.gvm.fullSphere || s.gvm.dimension >= 0));
console.log(`${path.basename(part)}: ${setups.length} setups, ${nonEmpty.length} non-empty GVMs, report ${fs.statSync(files.html).size} bytes`);

const browser = await chromium.launch({ executablePath: chromiumPath, headless: true,
  args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run"] });
try {
  const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
  const errors = [], requests = [];
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  page.on("pageerror", (e) => errors.push(String(e)));
  page.on("request", (r) => requests.push(r.url()));
  const started = Date.now();
  await page.goto("file://" + path.resolve(files.html));
  await page.waitForSelector("body[data-ready=true]", { timeout: 120000 });
  console.log(`loaded in ${Date.now() - started} ms`);
  check(errors.length === 0, `no console errors (${errors.join(" | ")})`);
  const outside = requests.filter((u) => !u.startsWith("file://") && !u.startsWith("data:"));
  check(outside.length === 0, `nothing fetched from outside the file (${outside.join(", ")})`);

  await page.screenshot({ path: `${base}-plan.png` });
  await checkSphere(page);
  await checkSnapshots(page);
  await checkColours(page);
  await checkAnalysisReport(browser);
} finally {
  await browser.close();
}
console.log(failures ? `${failures} check(s) failed` : "all checks passed");
process.exit(failures ? 1 : 0);

// The analysis report of the same part: it loads cleanly and draws every non-empty
// feature GVM (the features coloured by what their GVM is).
async function checkAnalysisReport(browser) {
  const html = `${base}-analysis.html`;
  execFileSync(gvm, ["analyze", part, "--report", html, "-q"], { stdio: "inherit" });
  const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
  const errors = [];
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  page.on("pageerror", (e) => errors.push(String(e)));
  await page.goto("file://" + path.resolve(html));
  await page.waitForSelector("body[data-ready=true]", { timeout: 120000 });
  check(errors.length === 0, `analysis report: no console errors (${errors.join(" | ")})`);
  const features = analysis.features.filter((s) => s.gvm && (s.gvm.fullSphere || s.gvm.dimension >= 0));
  const drawn = await page.evaluate(() => new Set([...document.querySelectorAll("svg.sphere .gvm")].map((g) => g.dataset.surface)).size);
  check(drawn === features.length, `analysis report: one shape per non-empty feature GVM (${drawn} = ${features.length})`);
  const views = await page.locator("figure.snapshot img").count();
  check(views === 6, `analysis report: six static views (${views})`);
  await page.screenshot({ path: `${base}-analysis.png` });
  await page.close();
}

// Lambert azimuthal equal-area as the report documents it: +z seen from above (+x right,
// +y up), -z seen from below (+x right, +y down); the hemisphere's edge at `radius`.
function project(v, panel) {
  const up = panel.pole === "+z";
  const z = up ? v.z || 0 : -(v.z || 0);
  const k = Math.sqrt(2 / (1 + z)) * (panel.radius / Math.SQRT2);
  return [panel.cx + k * (v.x || 0), panel.cy + (up ? -1 : 1) * k * (v.y || 0)];
}

async function checkSphere(page) {
  const svg = await page.evaluate(() => {
    const panels = [...document.querySelectorAll("svg.sphere .hemisphere")].map((g) => ({
      pole: g.dataset.pole, cx: +g.dataset.cx, cy: +g.dataset.cy, radius: +g.dataset.radius,
      marks: [...g.querySelectorAll(".setup-mark")].map((m) => ({ setup: +m.dataset.setup,
        circles: [...m.querySelectorAll("circle.mark")].map((c) => [+c.getAttribute("cx"), +c.getAttribute("cy")]) })),
      maps: [...g.querySelectorAll(".gvm")].map((m) => ({ surface: +m.dataset.surface,
        drawn: [...m.querySelectorAll("path")].some((p) => (p.getAttribute("d") || "").length > 2) ||
               m.querySelectorAll("circle").length > 0,
        points: [...m.querySelectorAll("circle.cell0")].map((c) => [+c.getAttribute("cx"), +c.getAttribute("cy")]) })),
    }));
    return panels;
  });
  check(svg.length === 2, "the sphere has two hemispheres");
  const markSetups = new Set(svg.flatMap((p) => p.marks.map((m) => m.setup)));
  check(markSetups.size === setups.length, `one mark per setup (${markSetups.size} marks, ${setups.length} setups)`);
  setups.forEach((s, i) => {
    const d = s.direction;
    const panel = svg.find((p) => (p.pole === "+z" ? (d.z || 0) >= 0 : (d.z || 0) <= 0));
    const [x, y] = project(d, panel);
    const circles = panel.marks.filter((m) => m.setup === i).flatMap((m) => m.circles);
    check(circles.some(([cx, cy]) => Math.hypot(cx - x, cy - y) < 0.5),
      `setup ${i + 1}'s mark is where its direction projects (${x.toFixed(1)}, ${y.toFixed(1)})`);
  });
  const drawn = new Set(svg.flatMap((p) => p.maps.filter((m) => m.drawn).map((m) => m.surface)));
  const groups = new Set(svg.flatMap((p) => p.maps.map((m) => m.surface)));
  check(groups.size === nonEmpty.length && nonEmpty.every((s) => drawn.has(s.id || 0)),
    `one drawn shape per non-empty GVM (${drawn.size} drawn, ${groups.size} groups, ${nonEmpty.length} non-empty GVMs)`);
  // Points are the through holes' axes: each must be a dot where it projects.
  let points = 0, found = 0;
  for (const s of nonEmpty) {
    for (const p of s.gvm.points || []) {
      const panel = svg.find((q) => (q.pole === "+z" ? (p.z || 0) >= 0 : (p.z || 0) <= 0));
      const [x, y] = project(p, panel);
      const dots = panel.maps.filter((m) => m.surface === (s.id || 0)).flatMap((m) => m.points);
      points++;
      if (dots.some(([cx, cy]) => Math.hypot(cx - x, cy - y) < 0.5)) found++;
    }
  }
  check(found === points, `every GVM point is a dot on the sphere (${found} of ${points})`);
}

async function checkSnapshots(page) {
  const shots = await page.evaluate(() => [...document.querySelectorAll("figure.snapshot[data-setup]")].map((f) => {
    const img = f.querySelector("img");
    return { setup: +f.dataset.setup, width: img.naturalWidth, complete: img.complete };
  }));
  check(shots.length === setups.length && shots.every((s) => s.complete && s.width > 0),
    `one decoded static picture per setup (${shots.length})`);
}

// The chromaticity of a colour: lighting scales a colour, it keeps this.
function chroma([r, g, b]) {
  const s = r + g + b || 1;
  return [r / s, g / s, b / s];
}

// Which setup colours the 3D view shows: pixels whose chromaticity is that of a setup
// colour (the report's colours pass through unlit-to-lit scaling unchanged in hue).
async function visibleSetupColours(page, palette) {
  const png = await page.locator("#part canvas").screenshot();
  const counts = await page.evaluate(async ({ data, palette }) => {
    const img = new Image();
    img.src = "data:image/png;base64," + data;
    await img.decode();
    const c = document.createElement("canvas");
    c.width = img.naturalWidth; c.height = img.naturalHeight;
    const ctx = c.getContext("2d");
    ctx.drawImage(img, 0, 0);
    const px = ctx.getImageData(0, 0, c.width, c.height).data;
    const counts = palette.map(() => 0);
    let nonWhite = 0;
    for (let i = 0; i < px.length; i += 4) {
      const r = px[i], g = px[i + 1], b = px[i + 2], s = r + g + b;
      if (s < 745) nonWhite++;
      if (s < 60) continue;
      palette.forEach((p, k) => {
        if (Math.abs(r / s - p[0]) + Math.abs(g / s - p[1]) + Math.abs(b / s - p[2]) < 0.03) counts[k]++;
      });
    }
    return { counts, nonWhite, total: px.length / 4 };
  }, { data: png.toString("base64"), palette });
  return counts;
}

async function checkColours(page) {
  const classes = await page.evaluate(() => JSON.parse(document.getElementById("gvm-report-data").textContent).classes);
  const setupColours = setups.map((_, i) => classes.find((c) => c.setup === i).color);
  const rgb = (hex) => [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16));
  const palette = [...new Set(setupColours)].map((hex) => chroma(rgb(hex)));
  const distinct = new Set(setupColours);
  check(distinct.size === setups.length, `every setup has its own colour (${distinct.size} colours)`);

  const first = await visibleSetupColours(page, palette);
  check(first.nonWhite > first.total * 0.02, `the 3D view is not blank (${first.nonWhite} of ${first.total} pixels drawn)`);
  const seen = new Set(palette.map((_, k) => k).filter((k) => first.counts[k] >= 30));
  // Looking along each setup (clicking its row), its own colour must show.
  for (let i = 0; i < setups.length; ++i) {
    await page.locator(`tr.setup-row[data-setup="${i}"]`).click();
    const k = [...distinct].indexOf(setupColours[i]);
    const view = await visibleSetupColours(page, palette);
    check(view.counts[k] >= 30, `looking along setup ${i + 1}, its colour shows (${view.counts[k]} pixels)`);
    if (view.counts[k] >= 30) seen.add(k);
    await page.screenshot({ path: `${base}-setup${i + 1}.png` });
  }
  check(seen.size === setups.length, `distinct setup colours visible = setups (${seen.size} = ${setups.length})`);
}
