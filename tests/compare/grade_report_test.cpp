// The grade report's text forms: names from the file system escaped in the HTML (so a folder named
// `<b>` cannot add markup), CSV fields quoted as RFC 4180 says, and the exit code the worst cell
// decides (anything not compared counts as a failure).
#include <limits>

#include <gtest/gtest.h>

#include "compare/grade_report.h"
#include "support/json.h"

namespace whitted {
namespace {

GradeCell compared(const std::string& scene, const std::string& student, Verdict v) {
    GradeCell c;
    c.scene = scene;
    c.student = student;
    c.status = CellStatus::compared;
    c.verdict = v;
    return c;
}

TEST(GradeReport, HtmlEscapesEverySpecialCharacter) {
    EXPECT_EQ(html_escape(R"(a<b>&"c'd)"), "a&lt;b&gt;&amp;&quot;c&#39;d");
    EXPECT_EQ(html_escape("plain"), "plain");
}

TEST(GradeReport, NamesFromTheFileSystemAreEscapedInThePage) {
    GradeReport r;
    r.scenes = {"s<&\"1"};
    r.students = {"<script>x</script>"};
    GradeCell c = compared(r.scenes[0], r.students[0], Verdict::fail);
    c.explanation = "looks like: <b>";
    c.image_file = "cell0.image.png";
    r.cells = {c};
    const std::string html = grade_html(r);
    EXPECT_EQ(html.find("<script>"), std::string::npos);
    EXPECT_EQ(html.find("s<&\"1"), std::string::npos);
    EXPECT_NE(html.find("s&lt;&amp;&quot;1"), std::string::npos);
    EXPECT_NE(html.find("&lt;script&gt;x&lt;/script&gt;"), std::string::npos);
    EXPECT_NE(html.find("looks like: &lt;b&gt;"), std::string::npos);
    EXPECT_NE(html.find("src=\"cell0.image.png\""), std::string::npos);
    EXPECT_EQ(html.find("http"), std::string::npos);  // nothing from the network
    EXPECT_EQ(html.find("<script"), std::string::npos);
}

TEST(GradeReport, CsvQuotesFieldsWithCommasAndQuotes) {
    GradeReport r;
    r.scenes = {"a,b"};
    r.students = {"x\"y"};
    GradeCell c;
    c.scene = "a,b";
    c.student = "x\"y";
    c.status = CellStatus::missing;
    c.problem = "no a,b.png";
    c.scene_file = "a,b.sc";
    r.cells = {c};
    EXPECT_EQ(grade_csv(r),
              "scene,student,result,psnr,flip_mean,ssim_worst,explanation,problem,scene_file\n"
              "\"a,b\",\"x\"\"y\",missing,,,,,\"no a,b.png\",\"a,b.sc\"\n");
}

TEST(GradeReport, ExitCodeIsTheWorstCell) {
    GradeReport r;
    r.cells = {compared("s", "a", Verdict::pass)};
    EXPECT_EQ(grade_exit_code(r), 0);
    r.cells.push_back(compared("s", "b", Verdict::warn));
    EXPECT_EQ(grade_exit_code(r), 1);
    GradeCell missing;
    missing.status = CellStatus::missing;
    r.cells.push_back(missing);
    EXPECT_EQ(grade_exit_code(r), 2);
    r.cells = {compared("s", "a", Verdict::fail)};
    EXPECT_EQ(grade_exit_code(r), 2);
}

TEST(GradeReport, JsonParsesBackWithNullMetricsForMissingCells) {
    GradeReport r;
    r.scenes = {"s"};
    r.students = {"a", "b"};
    GradeCell a = compared("s", "a", Verdict::pass);
    a.psnr = std::numeric_limits<double>::infinity();  // identical: no finite PSNR
    a.flip_mean = 0.0;
    GradeCell b;
    b.scene = "s";
    b.student = "b";
    b.status = CellStatus::wrong_size;
    b.problem = "10x10, not 48x36";
    r.cells = {a, b};
    const test::Json j = test::Json::parse(grade_json(r));
    EXPECT_EQ(j["exit_code"].number, 2);
    ASSERT_EQ(j["cells"].array.size(), 2u);
    EXPECT_EQ(j["cells"].array[0]["result"].string, "pass");
    EXPECT_TRUE(j["cells"].array[0]["psnr"].is_null());
    EXPECT_EQ(j["cells"].array[0]["flip_mean"].number, 0.0);
    EXPECT_EQ(j["cells"].array[1]["result"].string, "wrong size");
    EXPECT_EQ(j["cells"].array[1]["problem"].string, "10x10, not 48x36");
}

}  // namespace
}  // namespace whitted
