#include <defaultnormal_vertex>
vProbeSH0 = probeSH0; vProbeSH1 = probeSH1; vProbeSH2 = probeSH2; vProbeSH3 = probeSH3;
vProbeSH4 = probeSH4; vProbeSH5 = probeSH5; vProbeSH6 = probeSH6;
