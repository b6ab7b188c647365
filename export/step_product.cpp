#include "export/step_product.h"

#include "export/step_geometry.h"

namespace polarform {

int step_context(StepFile& f, double uncertainty_mm) {
  // ISO 10303-41 si_unit complex instances, supertypes in alphabetical order.
  const int mm = f.add("(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.))");
  const int rad = f.add("(NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.))");
  const int sr = f.add("(NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT())");
  // ISO 10303-43 uncertainty_measure_with_unit.
  const int unc = f.add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(" +
                        step_real(uncertainty_mm) + ")," + step_ref(mm) +
                        ",'distance_accuracy_value','confusion accuracy')");
  // ISO 10303-42 geometric_representation_context with global units and uncertainty.
  return f.add("(GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((" +
               step_ref(unc) + ")) GLOBAL_UNIT_ASSIGNED_CONTEXT((" + step_ref(mm) + "," +
               step_ref(rad) + "," + step_ref(sr) +
               ")) REPRESENTATION_CONTEXT('3D','3D context with units and uncertainty'))");
}

int step_origin_placement(StepFile& f) {
  return step_axis2(f, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                    Eigen::Vector3d::UnitX());
}

void step_product(StepFile& f, const std::string& name, int representation) {
  const std::string label = step_string(name.empty() ? "part" : name, "product name");
  // ISO 10303-214 (AUTOMOTIVE_DESIGN) application context and protocol.
  const int app = f.add("APPLICATION_CONTEXT('core data for automotive mechanical design processes')");
  f.add("APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000," +
        step_ref(app) + ")");
  const int pc = f.add("PRODUCT_CONTEXT(''," + step_ref(app) + ",'mechanical')");
  // ISO 10303-41 product_definition_schema: product, version, definition, shape.
  const int product = f.add("PRODUCT(" + label + "," + label + ",''," + "(" + step_ref(pc) + "))");
  f.add("PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(" + step_ref(product) + "))");
  const int pdf = f.add("PRODUCT_DEFINITION_FORMATION('',''," + step_ref(product) + ")");
  const int pdc = f.add("PRODUCT_DEFINITION_CONTEXT('part definition'," + step_ref(app) +
                        ",'design')");
  const int pd = f.add("PRODUCT_DEFINITION('design',''," + step_ref(pdf) + "," + step_ref(pdc) + ")");
  const int pds = f.add("PRODUCT_DEFINITION_SHAPE('',''," + step_ref(pd) + ")");
  f.add("SHAPE_DEFINITION_REPRESENTATION(" + step_ref(pds) + "," + step_ref(representation) + ")");
}

}  // namespace polarform
