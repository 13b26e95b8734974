// The report's data: the JSON block the C++ writer embeds (protobuf JSON of the Analysis
// and the Plan, the colour classes) and the part's triangles as typed arrays, each
// zlib-compressed and base64.

async function inflate(text) {
  const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate"));
  return new Response(stream).arrayBuffer();
}

export async function readReportData() {
  const data = JSON.parse(document.getElementById("gvm-report-data").textContent);
  const m = data.mesh;
  const [positions, triangles, triangleFace, faceClass, faceSurface] = await Promise.all(
    [m.positions, m.triangles, m.triangleFace, m.faceClass, m.faceSurface].map(inflate));
  data.mesh = {
    positions: new Float32Array(positions),
    triangles: new Uint32Array(triangles),
    triangleFace: new Uint32Array(triangleFace),
    faceClass: new Int32Array(faceClass),
    faceSurface: new Int32Array(faceSurface),
  };
  return data;
}

// The surfaces the report is about: the planned ones (features or regions), or the
// analysis's features.
export function surfacesOf(data) {
  const a = data.analysis;
  const regions = data.plan && data.plan.surfacesKind === "PLAN_SURFACES_REGIONS";
  return (regions ? a.regions : a.features) || [];
}

// Which setup reaches each surface (-1: none, whole; for one planned piece by piece, the
// words "pieces in setups 1, 6").
export function setupOfSurface(data) {
  const out = new Map();
  const unreachable = new Set(((data.plan && data.plan.unreachable) || []).map((u) => u.feature || 0));
  for (const s of (data.plan && data.plan.surfaces) || []) {
    const pieces = s.pieces && (s.pieces.setups || []).length && !unreachable.has(s.id || 0);
    out.set(s.id || 0, pieces ? `pieces in setups ${s.pieces.setups.map((k) => (k || 0) + 1).join(", ")}` : s.setup ?? 0);
  }
  return out;
}

export function isEmptyImage(image) {
  if (!image) return true;
  return !image.fullSphere && (image.dimension ?? 0) < 0;
}
