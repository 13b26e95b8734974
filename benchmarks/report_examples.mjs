// Reports for three shared parts of different kinds, with what they cost: the plan and
// report written by `gvm plan --report` (seconds), the file's size, and how long headless
// Chromium takes to open it until the page is ready (median of 3; software WebGL), plus a
// screenshot of each.
//
//   node benchmarks/report_examples.mjs --gvm build/release/service/gvm --out build/release/reports \
//        [--results benchmarks/results/reports.json] [PART...]
// Environment: GVM_NODE_MODULES (the build's node_modules), CHROMIUM (default /usr/bin/chromium).
import { execFileSync } from "node:child_process";
import { createRequire } from "node:module";
import fs from "node:fs";
import path from "node:path";

const here = path.dirname(new URL(import.meta.url).pathname);
const args = process.argv.slice(2);
const option = (name) => { const i = args.indexOf(name); return i >= 0 ? args.splice(i, 2)[1] : null; };
const gvm = option("--gvm"), out = option("--out"), results = option("--results");
const shared = path.resolve(here, "../../shared/data/parts");
const parts = args.length ? args : ["trimesh_plate_holes.STL", "trimesh_featuretype_from_step.off", "occt_brep_Bottom.off"]
  .map((p) => path.join(shared, p));
const { chromium } = createRequire(path.join(process.env.GVM_NODE_MODULES, "x.js"))("playwright-core");
fs.mkdirSync(out, { recursive: true });

const browser = await chromium.launch({ executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-background-networking"] });
const rows = [];
for (const part of parts) {
  const name = path.basename(part).replace(/\.[^.]*$/, "");
  const html = path.join(out, `${name}.html`), json = path.join(out, `${name}-plan.json`);
  const t0 = process.hrtime.bigint();
  execFileSync(gvm, ["plan", part, "--report", html, "--json", json, "-q", "--threads", "2"], { stdio: "inherit" });
  const writeSeconds = Number(process.hrtime.bigint() - t0) / 1e9;
  const plan = JSON.parse(fs.readFileSync(json, "utf8"));
  const loads = [];
  for (let k = 0; k < 3; ++k) {
    const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
    const start = Date.now();
    await page.goto("file://" + path.resolve(html));
    await page.waitForSelector("body[data-ready=true]", { timeout: 300000 });
    loads.push(Date.now() - start);
    if (k === 0) await page.screenshot({ path: path.join(out, `${name}.png`) });
    await page.close();
  }
  loads.sort((a, b) => a - b);
  const row = { part: path.basename(part), triangles: plan.part.triangles, setups: (plan.setups || []).length,
    unreachable: plan.unreachableCount || 0, planAndReportSeconds: +writeSeconds.toFixed(2),
    reportBytes: fs.statSync(html).size, loadMsMedian: loads[1], loadMs: loads };
  rows.push(row);
  console.log(JSON.stringify(row));
}
await browser.close();
if (results) fs.writeFileSync(results, JSON.stringify({ machine: "2 cores, headless Chromium with SwiftShader (software WebGL)", rows }, null, 2) + "\n");
