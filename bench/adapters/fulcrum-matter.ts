/**
 * fulcrum/matter: the matter-js adapter's own code (the same scene written in matter's API, the same
 * settings) run on Fulcrum's matter.js layer instead of matter-js.
 */
import FulcrumMatter from '../../src/matter/index';
import { MatterAdapter, type MatterModule } from './matter';

export class FulcrumMatterAdapter extends MatterAdapter {
  constructor() {
    super(FulcrumMatter as unknown as MatterModule);
  }
}
