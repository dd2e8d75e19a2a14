// The parts of three.js the page's 3D view of the cut stock uses, as one global `THREE` (the
// page is a classic script, offline, one file). Bundled by ./build.
export {
  WebGLRenderer, Scene, PerspectiveCamera, OrthographicCamera, BufferGeometry, BufferAttribute, Float32BufferAttribute,
  Mesh, MeshStandardMaterial, MeshBasicMaterial, LineBasicMaterial, LineSegments, Line, Group, AmbientLight, DirectionalLight,
  HemisphereLight, CylinderGeometry, ConeGeometry, SphereGeometry, BoxGeometry, EdgesGeometry, Color, Vector3, Box3, DoubleSide,
  AxesHelper, Spherical, MathUtils,
} from "three";
