// Renders a vega-lite spec to an SVG string, headless (no browser, no canvas).
import * as vega from 'vega'
import * as vegaLite from 'vega-lite'

export async function renderSvg(spec: vegaLite.TopLevelSpec): Promise<string> {
  const view = new vega.View(vega.parse(vegaLite.compile(spec).spec), { renderer: 'none' })
  const svg = await view.toSVG()
  view.finalize()
  return svg
}
