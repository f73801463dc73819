camera [ eye 0 0 5 focus 0 0 0 ]
mastersubgraph root [ trans [ object mesh [ file m.obj ] ] ]
===m.obj===
v 0 0 0v 1 0 0v 0 1 0f 1 2 99999