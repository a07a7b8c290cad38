// What the page's thread takes of three.js: the camera, the orbit controls and the math they use, from
// three's own source files, so that the viewer's script (viewer.js) carries these alone (92 KB, where
// 'three' as a whole brought its renderer: 292 KB). web/CMakeLists.txt bundles viewer.js with 'three'
// pointed here, for the orbit controls' own import of it. The renderer's worker takes 'three' whole.
export { Box3 } from './node_modules/three/src/math/Box3.js';
export { Controls } from './node_modules/three/src/extras/Controls.js';
export { MOUSE, TOUCH } from './node_modules/three/src/constants.js';
export * as MathUtils from './node_modules/three/src/math/MathUtils.js';
export { Plane } from './node_modules/three/src/math/Plane.js';
export { Quaternion } from './node_modules/three/src/math/Quaternion.js';
export { Ray } from './node_modules/three/src/math/Ray.js';
export { Spherical } from './node_modules/three/src/math/Spherical.js';
export { Vector2 } from './node_modules/three/src/math/Vector2.js';
export { Vector3 } from './node_modules/three/src/math/Vector3.js';
export { PerspectiveCamera } from './node_modules/three/src/cameras/PerspectiveCamera.js';
export { OrbitControls } from './node_modules/three/examples/jsm/controls/OrbitControls.js';
