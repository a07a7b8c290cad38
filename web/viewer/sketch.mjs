// The viewer's first frame: a mesh drawn by the CPU on a 2D canvas, so that the part shows before WebGL
// has started. Each triangle is flat in its first vertex's colour, lit as the site's pictures are (a light
// over the viewer's shoulder, both sides lit), drawn far to near (painter's order; a coarse mesh has few
// triangles that cross).
//   canvas: its width and height in device pixels; camera: a three.js camera, its matrices up to date;
//   mesh: {positions, colours (float32, 3 per vertex), indices (3 per triangle)}.
import { Vector3 } from './three_for_page.mjs';

export function drawSketch(canvas, camera, { positions, colours, indices }) {
  const context = canvas.getContext('2d', { willReadFrequently: true });  // drawn by the CPU: no GPU start
  const width = canvas.width, height = canvas.height;
  context.fillStyle = '#fff';
  context.fillRect(0, 0, width, height);
  const vertices = positions.length / 3, screen = new Float32Array(3 * vertices), v = new Vector3();
  for (let i = 0; i < vertices; ++i) {
    v.fromArray(positions, 3 * i).project(camera);
    screen.set([(v.x + 1) / 2 * width, (1 - v.y) / 2 * height, v.z], 3 * i);
  }
  const triangles = indices.length / 3, depth = new Float32Array(triangles);
  for (let t = 0; t < triangles; ++t)
    depth[t] = screen[3 * indices[3 * t] + 2] + screen[3 * indices[3 * t + 1] + 2] + screen[3 * indices[3 * t + 2] + 2];
  const order = Array.from({ length: triangles }, (_, t) => t).sort((a, b) => depth[b] - depth[a]);
  const toLight = new Vector3(1, 1, 2).normalize().transformDirection(camera.matrixWorld);
  const a = new Vector3(), b = new Vector3(), c = new Vector3();
  context.lineWidth = 1;
  for (const t of order) {
    const [i, j, k] = [indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]];
    a.fromArray(positions, 3 * i);
    b.fromArray(positions, 3 * j).sub(a);
    c.fromArray(positions, 3 * k).sub(a);
    const normal = b.cross(c);
    const length = normal.length();
    const shade = 0.35 + 0.65 * (length > 0 ? Math.abs(normal.dot(toLight)) / length : 0);
    const rgb = [0, 1, 2].map((q) => Math.round(255 * Math.min(1, colours[3 * i + q] * shade)));
    context.fillStyle = context.strokeStyle = `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;
    context.beginPath();
    context.moveTo(screen[3 * i], screen[3 * i + 1]);
    context.lineTo(screen[3 * j], screen[3 * j + 1]);
    context.lineTo(screen[3 * k], screen[3 * k + 1]);
    context.closePath();
    context.fill();
    context.stroke();  // no hairlines between neighbours
  }
}
